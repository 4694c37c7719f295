// `glint compare` on linear EXRs: the linear numbers (RMSE, PSNR against the reference's peak, SSIM
// on luminance) beside the 8-bit ones of the tone-mapped pictures, the tone map each file records,
// and one-line errors for a mixed pair and a malformed EXR.
#include "app/cli_runner.h"
#include "core/exr_image.h"
#include "core/image.h"
#include "metrics/image_comparison.h"
#include "render/tone_map.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

std::string args(std::initializer_list<std::string> parts) {
  std::string text;
  for (const std::string& part : parts) text += (text.empty() ? "" : " ") + part;
  return text;
}

// Linear colours up to 4 (the peak, at one pixel) and the same with +0.5 on every green value.
struct ExrPair {
  fs::path test, reference;
  ImageRgbaF test_image, reference_image;
};
ExrPair write_exr_pair(const TempFolder& folder, const std::string& tone_map = "aces") {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  ExrPair pair{folder.path() / "hybrid.exr", folder.path() / "rt.exr", {}, ImageRgbaF(32, 24)};
  for (glm::vec4& p : pair.reference_image.pixels) p = glm::vec4(value(random), value(random), value(random), 1.0f);
  pair.reference_image.at(10, 10) = glm::vec4(4.0f, 1.0f, 1.0f, 1.0f);
  pair.test_image = pair.reference_image;
  for (glm::vec4& p : pair.test_image.pixels) p.y += 0.5f;
  const ExrText text{{std::string(render::kExrToneMapAttribute), tone_map}};
  write_exr(pair.test, pair.test_image, text);
  write_exr(pair.reference, pair.reference_image, text);
  return pair;
}

TEST(CompareExrCli, IdenticalExrsGiveInfinitePsnrAndSsimOneInLinearAndToneMapped) {
  const TempFolder folder;
  const ExrPair pair = write_exr_pair(folder);
  const fs::path json = folder.path() / "same.json";
  const CliResult r = run_glint(args({"compare", quoted(pair.reference), quoted(pair.reference), "--json", quoted(json)}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  EXPECT_EQ(j["linear"]["rmse"]["overall"].get<double>(), 0.0);
  EXPECT_EQ(j["linear"]["psnr_db"]["overall"], "inf");
  EXPECT_EQ(j["linear"]["ssim_luminance"].get<double>(), 1.0);
  EXPECT_EQ(j["linear"]["peak"].get<double>(), 4.0);
  EXPECT_EQ(j["psnr_db"]["overall"], "inf");
  EXPECT_EQ(j["ssim"]["luma"].get<double>(), 1.0);
  for (const char* row : {"linear", "RMSE", "PSNR dB", "SSIM", "(luminance", "tone mapped to 8 bits: test aces"})
    EXPECT_NE(r.out.find(row), std::string::npos) << row << " missing from:\n" << r.out;
}

TEST(CompareExrCli, AKnownPerturbationGivesItsLinearRmseAndPsnrAndTheToneMappedNumbers) {
  const TempFolder folder;
  const ExrPair pair = write_exr_pair(folder, "reinhard");
  const fs::path json = folder.path() / "numbers.json";
  const CliResult r = run_glint(args({"compare", quoted(pair.test), quoted(pair.reference), "--json", quoted(json)}));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(read_text_file(json));
  const nlohmann::json& linear = j["linear"];
  EXPECT_NEAR(linear["rmse"]["g"].get<double>(), 0.5, 1e-7);
  EXPECT_EQ(linear["rmse"]["r"].get<double>(), 0.0);
  EXPECT_NEAR(linear["rmse"]["overall"].get<double>(), 0.5 / std::sqrt(3.0), 1e-7);
  EXPECT_EQ(linear["peak"].get<double>(), 4.0);
  EXPECT_NEAR(linear["psnr_db"]["overall"].get<double>(), 20.0 * std::log10(4.0 / (0.5 / std::sqrt(3.0))), 1e-5);
  EXPECT_NEAR(linear["psnr_db"]["g"].get<double>(), 20.0 * std::log10(4.0 / 0.5), 1e-5);  // 18.06 dB
  EXPECT_EQ(linear["psnr_db"]["r"], "inf");
  EXPECT_LT(linear["ssim_luminance"].get<double>(), 1.0);
  EXPECT_EQ(j["tone_map"]["test"], "reinhard");  // as the files record it

  // The 8-bit numbers are those of the pictures the renderer's tone map makes (reinhard, as recorded).
  const metrics::ImageComparison expected =
      metrics::compare_images(render::tone_map_to_rgba8(pair.test_image, render::ToneMap::reinhard),
                              render::tone_map_to_rgba8(pair.reference_image, render::ToneMap::reinhard));
  EXPECT_DOUBLE_EQ(j["rmse"]["overall"].get<double>(), expected.error.rmse);
  EXPECT_DOUBLE_EQ(j["ssim"]["luma"].get<double>(), expected.ssim.luma);
  EXPECT_GT(expected.error.rmse, 0.0);
  // --tone-map overrides the files' own.
  const CliResult aces =
      run_glint(args({"compare", quoted(pair.test), quoted(pair.reference), "--tone-map", "aces", "--json", quoted(json)}));
  ASSERT_EQ(aces.exit_code, 0) << aces.err;
  const nlohmann::json k = nlohmann::json::parse(read_text_file(json));
  EXPECT_EQ(k["tone_map"]["reference"], "aces");
  EXPECT_DOUBLE_EQ(k["rmse"]["overall"].get<double>(),
                   metrics::compare_images(render::tone_map_to_rgba8(pair.test_image, render::ToneMap::aces),
                                           render::tone_map_to_rgba8(pair.reference_image, render::ToneMap::aces))
                       .error.rmse);
}

TEST(CompareExrCli, AnExrWithAPngIsOneLineNamingBoth) {
  const TempFolder folder;
  const ExrPair pair = write_exr_pair(folder);
  const fs::path png = folder.path() / "rt.png";
  write_png(png, render::tone_map_to_rgba8(pair.reference_image, render::ToneMap::aces));
  for (const auto& [a, b] : {std::pair{pair.test, png}, std::pair{png, pair.test}}) {
    const CliResult r = run_glint(args({"compare", quoted(a), quoted(b)}));
    EXPECT_EQ(r.exit_code, 1);
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(pair.test.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(png.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("two EXRs or two PNGs"), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

TEST(CompareExrCli, MalformedOrMissingExrIsOneLineNamingTheFile) {
  const TempFolder folder;
  const ExrPair pair = write_exr_pair(folder);
  const std::string bytes = read_text_file(pair.reference);
  const fs::path truncated = folder.write("truncated.exr", std::string_view(bytes).substr(0, bytes.size() / 2));
  const fs::path text = folder.write("notes.exr", "not an EXR\n");
  const fs::path missing = folder.path() / "absent.exr";
  for (const auto& [bad, reason] :
       {std::pair{truncated, ""}, std::pair{text, "not an EXR file"}, std::pair{missing, "no such file"}}) {
    const CliResult r = run_glint(args({"compare", quoted(pair.test), quoted(bad)}));
    EXPECT_EQ(r.exit_code, 1) << bad;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("cannot read EXR '" + bad.string() + "'"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(reason), std::string::npos) << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

}  // namespace
}  // namespace glint::testing
