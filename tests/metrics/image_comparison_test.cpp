// compare_images bundles the metrics: the same numbers as calling each one, and one size check.
#include "metrics/image_comparison.h"

#include "metrics/metric_test_images.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::metrics {
namespace {

using glint::testing::error_of;
using glint::testing::random_rgba8;

TEST(ImageComparison, AgreesWithEachMetricCalledAlone) {
  const ImageRgba8 reference = random_rgba8(35, 26, 50);
  ImageRgba8 test = reference;
  for (std::size_t i = 0; i < test.pixels.size(); i += 3) test.pixels[i].y = static_cast<std::uint8_t>(255 - test.pixels[i].y);
  const ImageComparison c = compare_images(test, reference);
  EXPECT_EQ(c.width, 35);
  EXPECT_EQ(c.height, 26);
  const ColorBucketSimilarity buckets = color_bucket_similarity(test, reference);
  const RmsePsnr error = rmse_psnr(test, reference);
  EXPECT_EQ(c.buckets.channel_percent, buckets.channel_percent);
  EXPECT_EQ(c.buckets.mean_percent, buckets.mean_percent);
  EXPECT_EQ(c.error.channel_rmse, error.channel_rmse);
  EXPECT_EQ(c.error.psnr, error.psnr);
  EXPECT_EQ(c.ssim.luma, ssim(luma_plane(test), luma_plane(reference)).mean);
  EXPECT_EQ(c.ssim.channel[1], ssim(channel_plane(test, Channel::green), channel_plane(reference, Channel::green)).mean);
  EXPECT_EQ(c.ssim.channel[0], 1.0);  // only green was changed
  EXPECT_LT(c.ssim.channel[1], 1.0);
}

TEST(ImageComparison, SizeMismatchNamesBothFilesAndSizes) {
  const std::string message =
      error_of([] { compare_images(ImageRgba8(640, 480), ImageRgba8(320, 240), "frames/hybrid.png", "frames/rt.png"); });
  EXPECT_EQ(message,
            "cannot compare 'frames/hybrid.png' (640x480) with reference 'frames/rt.png' (320x240): the sizes differ");
}

TEST(ImageComparison, EmptyImagesAreAnError) {
  EXPECT_NE(error_of([] { compare_images(ImageRgba8(), ImageRgba8()); }).find("empty"), std::string::npos);
}

}  // namespace
}  // namespace glint::metrics
