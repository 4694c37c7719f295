// `glint info` end to end: the README's main job prints the paper's scene sizes, and --json is
// machine-readable with the same numbers.
#include "app/cli_runner.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

TEST(CliInfo, AtriumJsonHasThePapersCountsAndTwoDeformableMeshes) {
  const CliResult r = run_glint("info atrium --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json info = nlohmann::json::parse(r.out);
  EXPECT_NEAR(info["vertices"].get<double>(), 330'000, 0.05 * 330'000);
  EXPECT_NEAR(info["triangles"].get<double>(), 618'000, 0.05 * 618'000);
  int deformable = 0;
  for (const auto& mesh : info["meshes"]) deformable += mesh["deformable"].get<bool>() ? 1 : 0;
  EXPECT_EQ(deformable, 2);
  EXPECT_EQ(info["walkthrough"]["frames"].get<int>(), 4900);
  EXPECT_GT(info["walkthrough"]["camera_path_length"].get<double>(), 10.0);
}

TEST(CliInfo, TextOutputShowsCountsBoundsLightAndPaths) {
  const CliResult r = run_glint("info atrium-simple");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* field : {"vertices", "triangles", "bounds", "deformable  2 meshes", "materials", "textures", "light",
                            "walkthrough 4900 frames", "path length"})
    EXPECT_NE(r.out.find(field), std::string::npos) << field << " missing from:\n" << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

// Names come from files: a megabyte of name with escape sequences in it is printed bounded and escaped,
// in text and in JSON, as every message does (core/untrusted_text.h).
TEST(CliInfo, NamesFromTheFileAreBoundedAndEscaped) {
  const TempFolder temp;
  const std::string name = "\x1b[31m" + std::string(1'000'000, 'n');
  const std::filesystem::path obj = temp.write("long.obj", "o " + name + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  for (const char* json : {"", " --json"}) {
    const CliResult r = run_glint("info " + quoted(obj) + json);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_LT(r.out.size(), 20'000u) << json;
    EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << "the escape character is printed raw" << json;
    EXPECT_NE(r.out.find("bytes in all"), std::string::npos) << json;
  }
}

}  // namespace
}  // namespace glint::testing

namespace glint::testing {
namespace {

TEST(CliDevices, JsonAccountsForCudaAndOpenGlEitherWay) {
  const CliResult r = run_glint("devices --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json devices = nlohmann::json::parse(r.out);
  // Each of CUDA and OpenGL is either listed or explained, never silently absent.
  EXPECT_TRUE(!devices["cuda"].empty() || devices.contains("cuda_unavailable")) << r.out;
  EXPECT_TRUE(devices.contains("opengl") != devices.contains("opengl_unavailable")) << r.out;
  if (devices.contains("opengl")) {
    EXPECT_FALSE(devices["opengl"]["renderer"].get<std::string>().empty());
  }
}

}  // namespace
}  // namespace glint::testing
