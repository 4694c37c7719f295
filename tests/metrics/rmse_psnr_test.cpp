// RMSE and PSNR: exact values for known perturbations and agreement with a direct computation.
#include "metrics/rmse_psnr.h"

#include "metrics/metric_test_images.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint::metrics {
namespace {

using glint::testing::random_rgba8;

TEST(RmsePsnr, IdenticalImagesHaveZeroErrorAndInfinitePsnr) {
  const ImageRgba8 image = random_rgba8(23, 17, 10);
  const RmsePsnr e = rmse_psnr(image, image);
  EXPECT_EQ(e.rmse, 0.0);
  EXPECT_TRUE(std::isinf(e.psnr) && e.psnr > 0);
  for (std::size_t c = 0; c < 3; ++c) {
    EXPECT_EQ(e.channel_rmse[c], 0.0);
    EXPECT_TRUE(std::isinf(e.channel_psnr[c]) && e.channel_psnr[c] > 0);
  }
}

TEST(RmsePsnr, PlusTenOnRedGivesTheClosedFormValues) {
  const ImageRgba8 reference = random_rgba8(31, 29, 11, 0, 245);
  ImageRgba8 test = reference;
  for (glm::u8vec4& p : test.pixels) p.x = static_cast<std::uint8_t>(p.x + 10);
  const RmsePsnr e = rmse_psnr(test, reference);
  EXPECT_DOUBLE_EQ(e.channel_rmse[0], 10.0);
  EXPECT_EQ(e.channel_rmse[1], 0.0);
  EXPECT_EQ(e.channel_rmse[2], 0.0);
  EXPECT_DOUBLE_EQ(e.rmse, 10.0 / std::sqrt(3.0));
  EXPECT_DOUBLE_EQ(e.psnr, 20.0 * std::log10(255.0 / (10.0 / std::sqrt(3.0))));
  EXPECT_DOUBLE_EQ(e.channel_psnr[0], 20.0 * std::log10(25.5));
  EXPECT_TRUE(std::isinf(e.channel_psnr[1]));
  EXPECT_TRUE(std::isinf(e.channel_psnr[2]));
}

TEST(RmsePsnr, MatchesADirectComputationOnRandomImages) {
  const ImageRgba8 test = random_rgba8(27, 14, 12), reference = random_rgba8(27, 14, 13);
  double total = 0.0;
  double channel_sums[3] = {0.0, 0.0, 0.0};
  for (int y = 0; y < test.height; ++y)
    for (int x = 0; x < test.width; ++x)
      for (glm::length_t c = 0; c < 3; ++c) {
        const double d = double(test.at(x, y)[c]) - double(reference.at(x, y)[c]);
        channel_sums[c] += d * d;
        total += d * d;
      }
  const double n = 27.0 * 14.0;
  const RmsePsnr e = rmse_psnr(test, reference);
  for (std::size_t c = 0; c < 3; ++c) EXPECT_NEAR(e.channel_rmse[c], std::sqrt(channel_sums[c] / n), 1e-12);
  EXPECT_NEAR(e.rmse, std::sqrt(total / (3.0 * n)), 1e-12);
  EXPECT_NEAR(e.psnr, 20.0 * std::log10(255.0 / e.rmse), 1e-12);
}

TEST(RmsePsnr, BlackAgainstWhiteIsZeroDecibels) {
  const RmsePsnr e = rmse_psnr(ImageRgba8(3, 3, {0, 0, 0, 255}), ImageRgba8(3, 3, {255, 255, 255, 255}));
  EXPECT_DOUBLE_EQ(e.rmse, 255.0);
  EXPECT_DOUBLE_EQ(e.psnr, 0.0);
  EXPECT_DOUBLE_EQ(psnr_from_rmse(25.5), 20.0);
}

TEST(RmsePsnr, SizeMismatchIsAnError) {
  const std::string message = glint::testing::error_of([] { rmse_psnr(ImageRgba8(2, 2), ImageRgba8(2, 3)); });
  EXPECT_NE(message.find("(2x2)"), std::string::npos) << message;
  EXPECT_NE(message.find("(2x3)"), std::string::npos) << message;
}

}  // namespace
}  // namespace glint::metrics
