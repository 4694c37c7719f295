// The heat map: the documented ramp at its stops, known pixels, and Rec. 709 luma weighting.
#include "metrics/error_heatmap.h"

#include "metrics/metric_test_images.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::metrics {
namespace {

using glint::testing::error_of;

TEST(ErrorHeatmap, RampStopsAreBlackRedYellowWhite) {
  EXPECT_EQ(heat_ramp(0.0), glm::u8vec4(0, 0, 0, 255));
  EXPECT_EQ(heat_ramp(1.0 / 3.0), glm::u8vec4(255, 0, 0, 255));
  EXPECT_EQ(heat_ramp(2.0 / 3.0), glm::u8vec4(255, 255, 0, 255));
  EXPECT_EQ(heat_ramp(1.0), glm::u8vec4(255, 255, 255, 255));
  EXPECT_EQ(heat_ramp(0.5), glm::u8vec4(255, 128, 0, 255));  // halfway from red to yellow
  EXPECT_EQ(heat_ramp(7.0), glm::u8vec4(255, 255, 255, 255));  // clamped
  EXPECT_EQ(heat_ramp(-1.0), glm::u8vec4(0, 0, 0, 255));
}

TEST(ErrorHeatmap, IdenticalImagesAreBlack) {
  const ImageRgba8 image = glint::testing::random_rgba8(9, 7, 40);
  const ImageRgba8 heatmap = luma_error_heatmap(image, image);
  EXPECT_EQ(heatmap.width, 9);
  EXPECT_EQ(heatmap.height, 7);
  for (const glm::u8vec4& p : heatmap.pixels) ASSERT_EQ(p, glm::u8vec4(0, 0, 0, 255));
}

TEST(ErrorHeatmap, KnownGreyDifferencesLandOnKnownColours) {
  const ImageRgba8 reference(6, 5, {100, 100, 100, 255});
  ImageRgba8 test = reference;
  test.at(1, 1) = {130, 130, 130, 255};  // d = 30 = full scale   -> white
  test.at(4, 2) = {90, 90, 90, 255};     // d = 10 = 1/3 (darker) -> red
  test.at(2, 4) = {106, 106, 106, 255};  // d = 6  = 1/5          -> 0.6 red = 153
  HeatmapOptions options;
  options.full_scale = 30.0;
  const ImageRgba8 heatmap = luma_error_heatmap(test, reference, options);
  EXPECT_EQ(heatmap.at(1, 1), glm::u8vec4(255, 255, 255, 255));
  EXPECT_EQ(heatmap.at(4, 2), glm::u8vec4(255, 0, 0, 255));
  EXPECT_EQ(heatmap.at(2, 4), glm::u8vec4(153, 0, 0, 255));
  int black = 0;
  for (const glm::u8vec4& p : heatmap.pixels) black += p == glm::u8vec4(0, 0, 0, 255);
  EXPECT_EQ(black, 6 * 5 - 3);
}

TEST(ErrorHeatmap, ChannelsAreWeightedByRec709Luma) {
  // +100 on red alone is a luma difference of 21.26; at the default full scale of 64 that is
  // t = 0.3322, s = 3t = 0.99656, red = round(254.12) = 254. Blue alone (7.22) is much darker.
  const ImageRgba8 reference(2, 1, {50, 50, 50, 255});
  ImageRgba8 test = reference;
  test.at(0, 0).x = 150;
  test.at(1, 0).z = 150;
  const ImageRgba8 heatmap = luma_error_heatmap(test, reference);
  EXPECT_EQ(heatmap.at(0, 0), glm::u8vec4(254, 0, 0, 255));
  EXPECT_EQ(heatmap.at(1, 0), glm::u8vec4(86, 0, 0, 255));  // 3 * 7.22 / 64 * 255 = 86.3
}

TEST(ErrorHeatmap, BadScaleAndSizeMismatchAreErrors) {
  HeatmapOptions options;
  options.full_scale = 0.0;
  EXPECT_NE(error_of([&] { luma_error_heatmap(ImageRgba8(2, 2), ImageRgba8(2, 2), options); }).find("full scale"),
            std::string::npos);
  const std::string message = error_of([] { luma_error_heatmap(ImageRgba8(2, 2), ImageRgba8(3, 2)); });
  EXPECT_NE(message.find("(2x2)"), std::string::npos) << message;
  EXPECT_NE(message.find("(3x2)"), std::string::npos) << message;
}

}  // namespace
}  // namespace glint::metrics
