// `glint compare` end to end: the table, the JSON (same numbers as the library), the heat map, the
// --reference switch, and the error contract (one line naming the file, exit 1; bad flags exit 2).
#include "app/cli_runner.h"
#include "core/image.h"
#include "metrics/error_heatmap.h"
#include "metrics/image_comparison.h"
#include "metrics/metric_test_images.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

std::string args(std::initializer_list<std::string> parts) {
  std::string text;
  for (const std::string& part : parts) {
    if (!text.empty()) text += ' ';
    text += part;
  }
  return text;
}

// A random image and the same image with +10 on every red value, written as PNGs.
struct ImagePair {
  fs::path test, reference;
};
ImagePair write_pair(const TempFolder& folder, int width = 32, int height = 24) {
  const ImageRgba8 reference = random_rgba8(width, height, 60, 0, 245);
  ImageRgba8 test = reference;
  for (glm::u8vec4& p : test.pixels) p.x = static_cast<std::uint8_t>(p.x + 10);
  ImagePair pair{folder.path() / "hybrid.png", folder.path() / "rt.png"};
  write_png(pair.test, test);
  write_png(pair.reference, reference);
  return pair;
}

void expect_json_matches(const nlohmann::json& j, const metrics::ImageComparison& c) {
  const char* channels[] = {"r", "g", "b"};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(j["color_buckets_percent"][channels[i]].get<double>(), c.buckets.channel_percent[i]);
    EXPECT_DOUBLE_EQ(j["ssim"][channels[i]].get<double>(), c.ssim.channel[i]);
    EXPECT_DOUBLE_EQ(j["rmse"][channels[i]].get<double>(), c.error.channel_rmse[i]);
    if (std::isinf(c.error.channel_psnr[i]))
      EXPECT_EQ(j["psnr_db"][channels[i]], "inf");
    else
      EXPECT_DOUBLE_EQ(j["psnr_db"][channels[i]].get<double>(), c.error.channel_psnr[i]);
  }
  EXPECT_DOUBLE_EQ(j["color_buckets_percent"]["mean"].get<double>(), c.buckets.mean_percent);
  EXPECT_DOUBLE_EQ(j["ssim"]["luma"].get<double>(), c.ssim.luma);
  EXPECT_DOUBLE_EQ(j["rmse"]["overall"].get<double>(), c.error.rmse);
  EXPECT_DOUBLE_EQ(j["psnr_db"]["overall"].get<double>(), c.error.psnr);
  EXPECT_EQ(j["width"].get<int>(), c.width);
  EXPECT_EQ(j["height"].get<int>(), c.height);
}

TEST(CompareCli, PrintsTheTableAndWritesJsonAndHeatmapMatchingTheLibrary) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path json = folder.path() / "numbers.json", heatmap = folder.path() / "heat.png";
  const CliResult r = run_glint(args({"compare", quoted(pair.test), quoted(pair.reference), "--json", quoted(json),
                                      "--heatmap", quoted(heatmap)}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << r.err;
  for (const char* row : {"buckets %", "SSIM", "RMSE", "PSNR dB", "hybrid.png", "rt.png", "32x24"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << " missing from:\n" << r.out;

  const metrics::ImageComparison expected = metrics::compare_images(read_png(pair.test), read_png(pair.reference));
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  expect_json_matches(j, expected);
  EXPECT_EQ(j["test"], pair.test.string());
  EXPECT_EQ(j["reference"], pair.reference.string());
  EXPECT_NEAR(j["rmse"]["r"].get<double>(), 10.0, 1e-12);
  EXPECT_NEAR(j["rmse"]["overall"].get<double>(), 10.0 / std::sqrt(3.0), 1e-12);
  EXPECT_EQ(j["psnr_db"]["g"], "inf");

  const ImageRgba8 heat = read_png(heatmap);
  EXPECT_EQ(heat.width, 32);
  EXPECT_EQ(heat.height, 24);
  EXPECT_EQ(heat.pixels, metrics::luma_error_heatmap(read_png(pair.test), read_png(pair.reference)).pixels);

  // Written through temp files and renames: nothing else is left in the folder.
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder.path())) names.insert(entry.path().filename().string());
  EXPECT_EQ(names, (std::set<std::string>{"hybrid.png", "rt.png", "numbers.json", "heat.png"}));
}

TEST(CompareCli, IdenticalImagesGiveOneHundredPercentSsimOneAndInfinitePsnr) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path json = folder.path() / "same.json";
  const CliResult r = run_glint(args({"compare", quoted(pair.reference), quoted(pair.reference), "--json", quoted(json)}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  EXPECT_EQ(j["color_buckets_percent"]["mean"].get<double>(), 100.0);
  EXPECT_EQ(j["ssim"]["luma"].get<double>(), 1.0);
  EXPECT_EQ(j["rmse"]["overall"].get<double>(), 0.0);
  EXPECT_EQ(j["psnr_db"]["overall"], "inf");
  EXPECT_NE(r.out.find("inf"), std::string::npos) << r.out;
}

TEST(CompareCli, ReferenceASwapsTheRoles) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path json = folder.path() / "swapped.json";
  // A = the reference render, B = the perturbed one, and --reference a (case-insensitive).
  const CliResult r = run_glint(
      args({"compare", quoted(pair.reference), quoted(pair.test), "--reference", "a", "--json", quoted(json)}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  EXPECT_EQ(j["reference"], pair.reference.string());
  EXPECT_EQ(j["test"], pair.test.string());
  expect_json_matches(j, metrics::compare_images(read_png(pair.test), read_png(pair.reference)));
}

TEST(CompareCli, MissingFileIsOneLineNamingItWithExitCode1) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path missing = folder.path() / "no-such-frame.png";
  const CliResult r = run_glint(args({"compare", quoted(missing), quoted(pair.reference)}));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(missing.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(CompareCli, NonPngAndTruncatedPngAreOneLineErrorsNamingTheFile) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path text = folder.write("notes.png", "this is not an image\n");
  const std::string png_bytes = read_text_file(pair.reference);
  const fs::path truncated = folder.write("truncated.png", std::string_view(png_bytes).substr(0, 40));
  const fs::path directory = folder.path() / "frames.png";
  fs::create_directories(directory);
  for (const auto& [bad, reason] : {std::pair{text, "not a PNG file"}, std::pair{truncated, ""},
                                    std::pair{directory, "is a directory"}}) {
    const CliResult r = run_glint(args({"compare", quoted(pair.test), quoted(bad)}));
    EXPECT_EQ(r.exit_code, 1) << bad;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(bad.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
  }
}

TEST(CompareCli, SizeMismatchNamesBothFilesAndSizes) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path small = folder.path() / "small.png";
  write_png(small, random_rgba8(16, 16, 61));
  const CliResult r = run_glint(args({"compare", quoted(small), quoted(pair.reference)}));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  std::string expected = "cannot compare '";
  expected += small.string();
  expected += "' (16x16) with reference '";
  expected += pair.reference.string();
  expected += "' (32x24): the sizes differ";
  EXPECT_NE(r.err.find(expected), std::string::npos) << r.err;
}

TEST(CompareCli, UnwritableJsonFolderIsAnErrorAndLeavesNoFile) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path json = folder.path() / "missing-folder" / "out.json";
  const CliResult r = run_glint(args({"compare", quoted(pair.test), quoted(pair.reference), "--json", quoted(json)}));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(json.string()), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(json));
}

// --heatmap-scale is checked when the flags are parsed: 0 used to print CLI11's range with DBL_MAX
// written out (309 digits), nan passed and failed later with exit code 1.
TEST(CompareCli, HeatmapScaleOutsideZeroTo255IsAOneLineUsageError) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  const fs::path heatmap = folder.path() / "heat.png";
  for (const char* bad : {"0", "nan", "-nan", "inf", "-1", "255.5", "1e300", "12abc", ""}) {
    const CliResult r = run_glint(args({"compare", quoted(pair.test), quoted(pair.reference), "--heatmap",
                                        quoted(heatmap), "--heatmap-scale", std::string("\"") + bad + "\""}));
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
    const std::string first_line = r.err.substr(0, r.err.find('\n'));
    EXPECT_NE(first_line.find("--heatmap-scale: must be a number > 0 and <= 255"), std::string::npos) << r.err;
    EXPECT_LT(first_line.size(), 120u) << first_line;
    EXPECT_LE(line_count(r.err), 2) << r.err;  // the reason, and CLI11's pointer to --help
    EXPECT_FALSE(fs::exists(heatmap)) << bad;
  }
  for (const char* good : {"255", "0.5", "1e-3"}) {
    const CliResult r = run_glint(args({"compare", quoted(pair.test), quoted(pair.reference), "--heatmap",
                                        quoted(heatmap), "--heatmap-scale", good}));
    EXPECT_EQ(r.exit_code, 0) << good << "\n" << r.err;
  }
}

TEST(CompareCli, BadFlagsAreUsageErrorsWithExitCode2) {
  const TempFolder folder;
  const ImagePair pair = write_pair(folder);
  for (const std::string& bad :
       {args({"compare", quoted(pair.test), quoted(pair.reference), "--reference", "C"}),
        args({"compare", quoted(pair.test), quoted(pair.reference), "--no-such-flag"}),
        args({"compare", quoted(pair.test), quoted(pair.reference), "--heatmap-scale", "0"}),
        args({"compare", quoted(pair.test)})}) {
    const CliResult r = run_glint(bad);
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace glint::testing
