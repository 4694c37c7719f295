#include "metrics/color_buckets.h"

#include "metrics/image_size_check.h"

#include <algorithm>

namespace glint::metrics {

double bucket_similarity_percent(std::uint64_t test_sum, std::uint64_t reference_sum) {
  if (reference_sum == 0) return test_sum == 0 ? 100.0 : 0.0;
  const std::uint64_t difference = test_sum > reference_sum ? test_sum - reference_sum : reference_sum - test_sum;
  const double relative = static_cast<double>(difference) / static_cast<double>(reference_sum);
  return 100.0 * std::clamp(1.0 - relative, 0.0, 1.0);
}

ColorBucketSimilarity color_bucket_similarity(const ImageRgba8& test, const ImageRgba8& reference,
                                              std::string_view test_name, std::string_view reference_name) {
  require_same_size(test, reference, test_name, reference_name);
  ColorBucketSimilarity result;
  // Integer sums are exact (a 2^32-pixel image of 255s still fits in 64 bits), so the result does
  // not depend on summation order.
  for (std::size_t i = 0; i < test.pixels.size(); ++i)
    for (glm::length_t c = 0; c < 3; ++c) {
      result.test_sums[static_cast<std::size_t>(c)] += test.pixels[i][c];
      result.reference_sums[static_cast<std::size_t>(c)] += reference.pixels[i][c];
    }
  double total = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    result.channel_percent[c] = bucket_similarity_percent(result.test_sums[c], result.reference_sums[c]);
    total += result.channel_percent[c];
  }
  result.mean_percent = total / 3.0;
  return result;
}

}  // namespace glint::metrics
