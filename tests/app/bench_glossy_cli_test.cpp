// `glint bench --experiment glossy` as a user runs it, quick and tiny: the report, glossy.csv and
// summary.json hold every configuration's row and the reference, the reference is cached for a
// second run, mirror reflections held still do not flicker while 1-sample glossy ones do, and bad
// flags are one line.
#include "app/cli_runner.h"
#include "core/image.h"
#include "glossy_room_scene.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using BenchGlossyCli = GlTest;  // skips without headless OpenGL 4.5

const std::vector<std::string> kLabels = {"hybrid-mirror", "ssr",    "ssr+denoise", "hybrid",
                                          "hybrid+denoise", "rt", "rt+denoise"};

TEST_F(BenchGlossyCli, QuickRunReportsEveryConfigurationAgainstACachedReference) {
  TempFolder folder;
  const fs::path scene = write_glossy_room(folder);
  const fs::path out = folder.path() / "bench";
  const std::string command = "bench --experiment glossy --quick --scene " + quoted(scene) + " --simple-scene " +
                              quoted(scene) + " --width 32 --height 18 --reference-spp 4 --flicker-frames 2 --out " +
                              quoted(out);
  CliResult r = run_glint(command);
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const fs::path reference = out / "references" / "room.scene" / "frame_01800.png";
  ASSERT_TRUE(fs::exists(reference));
  const ImageRgba8 image = read_png(reference);
  EXPECT_EQ(image.width, 32);
  EXPECT_EQ(image.height, 18);
  EXPECT_TRUE(fs::exists(reference.parent_path() / "reference.json"));

  const auto csv = read_csv(out / "glossy.csv");
  ASSERT_EQ(csv.size(), 1 + kLabels.size()) << "header + one row per configuration at frame 1800";
  std::set<std::string> labels;
  for (std::size_t row = 1; row < csv.size(); ++row) {
    ASSERT_EQ(csv[row].size(), csv[0].size());
    EXPECT_EQ(csv[row][1], "1800");
    labels.insert(csv[row][2]);
  }
  EXPECT_EQ(labels, std::set<std::string>(kLabels.begin(), kLabels.end()));

  const std::string report = read_text_file(out / "report.md");
  EXPECT_NE(report.find("reference: rt, 4 samples per pixel"), std::string::npos) << report;
  for (const std::string& label : kLabels) EXPECT_NE(report.find("| " + label + " |"), std::string::npos) << label;

  const nlohmann::json summary = nlohmann::json::parse(read_text_file(out / "summary.json"));
  EXPECT_EQ(summary["experiment"], "glossy");
  ASSERT_EQ(summary["scenes"].size(), 1u) << "--scene and --simple-scene are the same scene";
  const nlohmann::json& entry = summary["scenes"][0];
  EXPECT_EQ(entry["reference"]["rendered_frames"], 1);
  ASSERT_EQ(entry["configs"].size(), kLabels.size());
  for (const nlohmann::json& config : entry["configs"]) {
    SCOPED_TRACE(config["label"].get<std::string>());
    EXPECT_GT(config["ssim"].get<double>(), 0.0);
    EXPECT_LE(config["ssim"].get<double>(), 1.0);
    EXPECT_GE(config["flicker_walkthrough_percent"].get<double>(), 0.0);
    if (config["label"] == "hybrid-mirror") {
      EXPECT_EQ(config["flicker_still_percent"].get<double>(), 0.0) << "mirrors held still are the same image";
    }
    if (config["label"] == "rt") {
      EXPECT_GT(config["flicker_still_percent"].get<double>(), 0.0) << "one GGX sample a frame changes every frame";
    }
  }

  r = run_glint(command);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json again = nlohmann::json::parse(read_text_file(out / "summary.json"));
  EXPECT_EQ(again["scenes"][0]["reference"]["cached_frames"], 1) << "the reference is read back, not rendered";
  EXPECT_EQ(again["scenes"][0]["reference"]["rendered_frames"], 0);
}

TEST(BenchGlossyFlags, BadValuesAreOneLine) {
  TempFolder folder;
  const std::string out = " --out " + quoted(folder.path() / "bench");
  for (const char* flags : {"--flicker-frames 1", "--reference-spp 0", "--flicker-frames x"}) {
    SCOPED_TRACE(flags);
    const CliResult r = run_glint(std::string("bench --experiment glossy --quick ") + flags + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_LE(line_count(r.err), 2) << r.err;  // the reason, and CLI11's pointer to --help
    EXPECT_NE(r.err.find(std::string(flags).substr(0, std::string(flags).find(' '))), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(folder.path() / "bench"));
}

TEST_F(BenchGlossyCli, NoQualityFrameBelowFramesIsOneLine) {
  TempFolder folder;
  const fs::path scene = write_glossy_room(folder);
  const CliResult r = run_glint("bench --experiment glossy --quick --scene " + quoted(scene) + " --simple-scene " +
                                quoted(scene) + " --frames 100 --out " + quoted(folder.path() / "bench"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--frames 100: none of the quality frames"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(folder.path() / "bench"));
}

}  // namespace
}  // namespace glint::testing
