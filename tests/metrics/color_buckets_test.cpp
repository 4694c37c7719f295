// The paper's colour-bucket similarity: exact sums, the documented formula, its edge cases, and its
// known blindness to where colours are.
#include "metrics/color_buckets.h"

#include "metrics/metric_test_images.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace glint::metrics {
namespace {

using glint::testing::error_of;
using glint::testing::random_rgba8;
using glint::testing::uniform_rgba8;

TEST(ColorBuckets, IdenticalImagesAreOneHundredPercentOnEveryChannel) {
  const ImageRgba8 image = random_rgba8(37, 21, 1);
  const ColorBucketSimilarity s = color_bucket_similarity(image, image);
  for (double percent : s.channel_percent) EXPECT_EQ(percent, 100.0);
  EXPECT_EQ(s.mean_percent, 100.0);
}

TEST(ColorBuckets, SumsMatchBruteForce) {
  const ImageRgba8 test = random_rgba8(19, 13, 2), reference = random_rgba8(19, 13, 3);
  const ColorBucketSimilarity s = color_bucket_similarity(test, reference);
  for (glm::length_t c = 0; c < 3; ++c) {
    std::uint64_t test_sum = 0, reference_sum = 0;
    for (int y = 0; y < test.height; ++y)
      for (int x = 0; x < test.width; ++x) {
        test_sum += test.at(x, y)[c];
        reference_sum += reference.at(x, y)[c];
      }
    EXPECT_EQ(s.test_sums[static_cast<std::size_t>(c)], test_sum);
    EXPECT_EQ(s.reference_sums[static_cast<std::size_t>(c)], reference_sum);
  }
}

TEST(ColorBuckets, PlusTenOnRedLowersOnlyRedByTenPixelsWorthOfItsBucket) {
  const ImageRgba8 reference = random_rgba8(40, 30, 4, 0, 245);
  ImageRgba8 test = reference;
  for (glm::u8vec4& p : test.pixels) p.x = static_cast<std::uint8_t>(p.x + 10);
  const ColorBucketSimilarity s = color_bucket_similarity(test, reference);
  const double pixels = 40.0 * 30.0;
  const double red_sum = static_cast<double>(s.reference_sums[0]);
  const double expected_red = 100.0 * (1.0 - 10.0 * pixels / red_sum);
  EXPECT_EQ(s.test_sums[0], s.reference_sums[0] + 10 * 40 * 30);
  EXPECT_NEAR(s.channel_percent[0], expected_red, 1e-12);
  EXPECT_LT(s.channel_percent[0], 100.0);
  EXPECT_EQ(s.channel_percent[1], 100.0);
  EXPECT_EQ(s.channel_percent[2], 100.0);
  EXPECT_NEAR(s.mean_percent, (expected_red + 200.0) / 3.0, 1e-12);
}

TEST(ColorBuckets, ErrorsOfEitherSignCountTheSame) {
  const ImageRgba8 reference = uniform_rgba8(8, 8, {100, 100, 100, 255});
  const ColorBucketSimilarity brighter = color_bucket_similarity(uniform_rgba8(8, 8, {110, 100, 100, 255}), reference);
  const ColorBucketSimilarity darker = color_bucket_similarity(uniform_rgba8(8, 8, {90, 100, 100, 255}), reference);
  EXPECT_NEAR(brighter.channel_percent[0], 90.0, 1e-12);
  EXPECT_NEAR(darker.channel_percent[0], 90.0, 1e-12);
}

TEST(ColorBuckets, IsBlindToWherePixelsAre) {
  // The documented weakness: a mirrored image has the same sums, so it scores 100 %.
  const ImageRgba8 reference = random_rgba8(16, 9, 5);
  ImageRgba8 mirrored = reference;
  for (int y = 0; y < reference.height; ++y)
    for (int x = 0; x < reference.width; ++x) mirrored.at(x, y) = reference.at(reference.width - 1 - x, y);
  ASSERT_NE(mirrored.pixels, reference.pixels);
  EXPECT_EQ(color_bucket_similarity(mirrored, reference).mean_percent, 100.0);
}

TEST(ColorBuckets, MoreThanTwiceTheReferenceClampsToZero) {
  const ColorBucketSimilarity s =
      color_bucket_similarity(uniform_rgba8(4, 4, {250, 30, 20, 255}), uniform_rgba8(4, 4, {100, 10, 10, 255}));
  EXPECT_EQ(s.channel_percent[0], 0.0);   // 1 - 150/100 < 0
  EXPECT_EQ(s.channel_percent[1], 0.0);   // 1 - 20/10 < 0
  EXPECT_EQ(s.channel_percent[2], 0.0);   // 1 - 10/10 = 0
}

TEST(ColorBuckets, EmptyReferenceBucketIsAllOrNothing) {
  const ImageRgba8 black = uniform_rgba8(5, 5, {0, 0, 0, 255});
  EXPECT_EQ(color_bucket_similarity(black, black).mean_percent, 100.0);
  ImageRgba8 one_red_level = black;
  one_red_level.at(2, 2).x = 1;
  const ColorBucketSimilarity s = color_bucket_similarity(one_red_level, black);
  EXPECT_EQ(s.channel_percent[0], 0.0);
  EXPECT_EQ(s.channel_percent[1], 100.0);
  EXPECT_EQ(bucket_similarity_percent(0, 0), 100.0);
  EXPECT_EQ(bucket_similarity_percent(7, 0), 0.0);
}

TEST(ColorBuckets, AlphaIsIgnored) {
  const ImageRgba8 reference = random_rgba8(6, 6, 6);
  ImageRgba8 test = reference;
  for (glm::u8vec4& p : test.pixels) p.w = 0;
  EXPECT_EQ(color_bucket_similarity(test, reference).mean_percent, 100.0);
}

TEST(ColorBuckets, SizeMismatchNamesBothImagesAndSizes) {
  const std::string message = error_of([] {
    color_bucket_similarity(ImageRgba8(4, 3), ImageRgba8(3, 4), "render.png", "reference.png");
  });
  EXPECT_EQ(message, "cannot compare 'render.png' (4x3) with reference 'reference.png' (3x4): the sizes differ");
}

}  // namespace
}  // namespace glint::metrics
