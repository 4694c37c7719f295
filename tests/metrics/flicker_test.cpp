// The flicker metric (metrics/flicker.h): 0 for a sequence of equal images, the mean absolute luma
// change over the mean luma for a known change, wherever it happens, and errors for fewer than two
// frames or frames of different sizes.
#include "metrics/flicker.h"

#include "core/error.h"

#include <gtest/gtest.h>

namespace glint::metrics {
namespace {

ImageRgba8 grey(int width, int height, std::uint8_t value) {
  return ImageRgba8(width, height, glm::u8vec4(value, value, value, 255));
}

TEST(Flicker, EqualImagesHaveNone) {
  const ImageRgba8 image = grey(8, 4, 120);
  const Flicker flicker = measure_flicker({image, image, image});
  EXPECT_EQ(flicker.ratio, 0.0);
  EXPECT_EQ(flicker.mean_abs_change, 0.0);
  EXPECT_DOUBLE_EQ(flicker.mean_luma, 120.0);
  EXPECT_EQ(flicker.frames, 3u);
}

TEST(Flicker, KnownChangeOverMeanLuma) {
  // 100 -> 110 -> 100: every pixel changes by 10 twice; mean luma (100 + 110 + 100) / 3.
  const Flicker flicker = measure_flicker({grey(6, 5, 100), grey(6, 5, 110), grey(6, 5, 100)});
  EXPECT_DOUBLE_EQ(flicker.mean_abs_change, 10.0);
  EXPECT_NEAR(flicker.mean_luma, 310.0 / 3.0, 1e-12);
  EXPECT_NEAR(flicker.ratio, 10.0 / (310.0 / 3.0), 1e-12);
}

TEST(Flicker, AbsoluteChangeOfSomePixelsIsAveragedOverTheImage) {
  // A quarter of the pixels goes 200 -> 0 (a change of 200, counted as its absolute value), the
  // rest stays at 200: mean change 50, mean luma (200 + 150) / 2 = 175.
  ImageRgba8 first = grey(4, 4, 200), second = first;
  for (int x = 0; x < 4; ++x) second.at(x, 1) = glm::u8vec4(0, 0, 0, 255);
  const Flicker flicker = measure_flicker({first, second});
  EXPECT_DOUBLE_EQ(flicker.mean_abs_change, 50.0);
  EXPECT_DOUBLE_EQ(flicker.mean_luma, 175.0);
  EXPECT_DOUBLE_EQ(flicker.ratio, 50.0 / 175.0);
  // Luma, not RGB: a pure blue change weighs 0.0722 of a grey one.
  ImageRgba8 blue = grey(4, 4, 0);
  for (glm::u8vec4& pixel : blue.pixels) pixel.z = 100;
  EXPECT_NEAR(measure_flicker({grey(4, 4, 0), blue}).mean_abs_change, 7.22, 1e-9);
}

TEST(Flicker, BlackFramesHaveNoneAndBadSequencesAreErrors) {
  EXPECT_EQ(measure_flicker({grey(4, 4, 0), grey(4, 4, 0)}).ratio, 0.0);
  EXPECT_THROW((void)measure_flicker({grey(4, 4, 10)}), Error);
  EXPECT_THROW((void)measure_flicker({grey(4, 4, 10), grey(5, 4, 10)}), Error);
  FlickerMeter meter;
  EXPECT_THROW(meter.add(ImageRgba8()), Error);
}

}  // namespace
}  // namespace glint::metrics
