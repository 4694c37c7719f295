// Every committed fuzz input (fuzz/corpus/<target>/ seeds and fuzz/regressions/<target>/ inputs that
// once crashed a loader) goes through its target's entry function, as the libFuzzer programs run it:
// a glint::Error is a correct answer, any other exception fails the test, and under the asan preset a
// memory or undefined-behaviour error aborts it.
#include "fuzz_entries.h"

#include "core/error.h"
#include "core/log.h"
#include "support/test_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace glint {
namespace {

std::vector<std::uint8_t> file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The files of fuzz/<kind>/<target>/, sorted so that failures read the same on every run.
std::vector<std::filesystem::path> inputs(const std::string& kind, std::string_view target) {
  const std::filesystem::path folder = testing::source_dir() / "fuzz" / kind / target;
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(folder))
    for (const auto& entry : std::filesystem::directory_iterator(folder))
      if (entry.is_regular_file()) files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// "" when the input is handled (loaded, or rejected with a glint::Error), else what escaped.
std::string outcome(const fuzz::FuzzTarget& target, const std::filesystem::path& file) {
  const std::vector<std::uint8_t> bytes = file_bytes(file);
  const ScopedLogCapture quiet;  // the loaders' warnings about bad inputs are expected
  try {
    target.entry(bytes);
  } catch (const Error&) {
  } catch (const std::exception& e) {
    return std::string("exception: ") + e.what();
  } catch (...) {
    return "a non-standard exception";
  }
  return "";
}

class FuzzCorpusReplay : public ::testing::TestWithParam<std::string_view> {};

TEST_P(FuzzCorpusReplay, EveryCommittedInputLoadsOrFailsWithAGlintError) {
  const fuzz::FuzzTarget* target = fuzz::find_fuzz_target(GetParam());
  ASSERT_NE(target, nullptr);
  const std::vector<std::filesystem::path> seeds = inputs("corpus", target->name);
  EXPECT_FALSE(seeds.empty()) << "no seed corpus in fuzz/corpus/" << target->name;
  std::vector<std::filesystem::path> all = seeds;
  const std::vector<std::filesystem::path> regressions = inputs("regressions", target->name);
  all.insert(all.end(), regressions.begin(), regressions.end());
  for (const std::filesystem::path& file : all) EXPECT_EQ(outcome(*target, file), "") << file;
}

INSTANTIATE_TEST_SUITE_P(Targets, FuzzCorpusReplay,
                         ::testing::Values("obj_mtl", "gltf", "scene_json", "texture"),
                         [](const ::testing::TestParamInfo<std::string_view>& param_info) { return std::string(param_info.param); });

TEST(FuzzTargets, EveryTargetHasAFolderNameAndAnEntry) {
  ASSERT_EQ(fuzz::fuzz_targets().size(), 4u);
  for (const fuzz::FuzzTarget& target : fuzz::fuzz_targets()) {
    EXPECT_NE(target.entry, nullptr) << target.name;
    EXPECT_EQ(fuzz::find_fuzz_target(target.name), &target);
  }
  EXPECT_EQ(fuzz::find_fuzz_target("png"), nullptr);
}

// The harness itself: the OBJ part and the MTL part are loaded as f.obj and f.mtl beside it, so that
// the fuzzer reaches the MTL reader through the OBJ's `mtllib`.
TEST(FuzzEntries, ObjAndMtlPartsAreBothLoaded) {
  const std::string input = "mtllib f.mtl\nusemtl shiny\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3" +
                            std::string(fuzz::kObjMtlSeparator) + "newmtl shiny\nKd 0.5 abc\n";
  const ScopedLogCapture quiet;
  // The MTL's malformed Kd can only be reported if the MTL part was written where the OBJ looks.
  try {
    fuzz::load_obj_and_mtl({reinterpret_cast<const std::uint8_t*>(input.data()), input.size()});
    FAIL() << "expected the MTL part's error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("f.mtl:2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace glint
