// metrics/linear_metrics.h: RMSE, PSNR against the reference's peak and SSIM on luminance of linear
// colour, on images whose answers are known.
#include "metrics/linear_metrics.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace glint::testing {
namespace {

// HDR values: most below 1, a few highlights up to 8.
ImageRgbaF random_linear(int width, int height, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> value(0.0f, 1.0f);
  ImageRgbaF image(width, height);
  for (glm::vec4& p : image.pixels) p = glm::vec4(value(random), value(random), value(random), 1.0f);
  image.at(3, 4) = glm::vec4(8.0f, 2.0f, 0.5f, 1.0f);  // the reference's peak: 8
  return image;
}

TEST(LinearMetrics, IdenticalImagesHaveZeroErrorInfinitePsnrAndSsimOne) {
  const ImageRgbaF image = random_linear(32, 24, 1);
  const metrics::LinearComparison c = metrics::compare_linear_images(image, image);
  EXPECT_EQ(c.rmse, 0.0);
  EXPECT_TRUE(std::isinf(c.psnr) && c.psnr > 0);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_TRUE(std::isinf(c.channel_psnr[i]));
  EXPECT_EQ(c.ssim_luminance, 1.0);
  EXPECT_EQ(c.peak, 8.0);
}

TEST(LinearMetrics, AKnownOffsetGivesItsRmseAndPsnrAgainstTheReferencePeak) {
  const ImageRgbaF reference = random_linear(32, 24, 2);
  ImageRgbaF test = reference;
  for (glm::vec4& p : test.pixels) p.x += 0.25f;  // rounded to float: 0.25 within 3e-8
  test.at(3, 4).x = 8.25f;
  const metrics::LinearComparison c = metrics::compare_linear_images(test, reference);
  EXPECT_NEAR(c.channel_rmse[0], 0.25, 1e-7);
  EXPECT_EQ(c.channel_rmse[1], 0.0);
  EXPECT_EQ(c.channel_rmse[2], 0.0);
  EXPECT_NEAR(c.rmse, 0.25 / std::sqrt(3.0), 1e-7);
  EXPECT_EQ(c.peak, 8.0);
  EXPECT_NEAR(c.psnr, 20.0 * std::log10(8.0 / (0.25 / std::sqrt(3.0))), 1e-5);  // 34.85 dB
  EXPECT_NEAR(c.channel_psnr[0], 20.0 * std::log10(8.0 / 0.25), 1e-5);         // 30.10 dB
  // A constant offset of red moves every luminance by 0.2126 x 0.25: the luminance term only.
  EXPECT_LT(c.ssim_luminance, 1.0);
  EXPECT_GT(c.ssim_luminance, 0.9);
  // Test and reference swapped: the same error, a different peak.
  const metrics::LinearComparison swapped = metrics::compare_linear_images(reference, test);
  EXPECT_NEAR(swapped.rmse, c.rmse, 1e-12);
  EXPECT_EQ(swapped.peak, 8.25);
}

TEST(LinearMetrics, LuminanceIsRec709OfLinearValues) {
  ImageRgbaF image(1, 1);
  image.at(0, 0) = glm::vec4(1.0f, 2.0f, 4.0f, 1.0f);
  EXPECT_NEAR(metrics::luminance_plane(image).at(0, 0), 0.2126 + 2 * 0.7152 + 4 * 0.0722, 1e-12);
}

TEST(LinearMetrics, SizeMismatchAndNonFiniteValuesAreErrorsNamingTheImages) {
  const ImageRgbaF a = random_linear(32, 24, 3), b = random_linear(24, 32, 4);
  EXPECT_NE(error_of([&] { metrics::compare_linear_images(a, b, "a.exr", "b.exr"); }).find("'b.exr' (24x32)"),
            std::string::npos);
  ImageRgbaF bad = a;
  bad.at(5, 6).y = std::numeric_limits<float>::quiet_NaN();
  const std::string message = error_of([&] { metrics::require_finite(bad, "bad.exr"); });
  EXPECT_NE(message.find("'bad.exr': pixel (5, 6)"), std::string::npos) << message;
  metrics::require_finite(a, "a.exr");  // no error
}

}  // namespace
}  // namespace glint::testing
