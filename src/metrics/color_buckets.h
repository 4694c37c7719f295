#pragma once
// The paper's image-quality measure ("colour buckets", Macedo & Rodrigues, section on image quality):
// every channel value of every pixel is added to that channel's bucket, and each bucket of the test
// image is compared with the same bucket of the ray-traced reference.
//
// Exact definition used here (the paper gives it only in words), for c in R, G, B over all N pixels:
//   S_c(img)     = sum over pixels of the 8-bit value of channel c          (exact, 64-bit integer)
//   similarity_c = 100 * clamp(1 - |S_c(test) - S_c(ref)| / S_c(ref), 0, 1)      when S_c(ref) > 0
//                = 100 if S_c(test) = 0, else 0                                 when S_c(ref) = 0
//   mean         = (similarity_R + similarity_G + similarity_B) / 3
// Alpha is ignored. The clamp keeps the value a percentage when the test bucket is more than twice
// the reference bucket; the S_c(ref) = 0 case is the limit of the clamped formula.
//
// Weakness: only the sums are compared, so the measure is blind to where colours are. Moving,
// mirroring or swapping pixels scores 100 %, and errors of opposite sign cancel. Read it next to
// SSIM and RMSE (docs/metrics.md).
#include "core/image.h"
#include "metrics/image_size_check.h"

#include <array>
#include <cstdint>
#include <string_view>

namespace glint::metrics {

struct ColorBucketSimilarity {
  std::array<double, 3> channel_percent{};            // R, G, B, each 0..100
  double mean_percent = 0.0;                          // mean of the three
  std::array<std::uint64_t, 3> test_sums{};           // S_c(test)
  std::array<std::uint64_t, 3> reference_sums{};      // S_c(ref)
};

// Throws a glint::Error naming both images when their sizes differ.
ColorBucketSimilarity color_bucket_similarity(const ImageRgba8& test, const ImageRgba8& reference,
                                              std::string_view test_name = kDefaultTestName,
                                              std::string_view reference_name = kDefaultReferenceName);

// similarity_c from two bucket sums, as defined above.
double bucket_similarity_percent(std::uint64_t test_sum, std::uint64_t reference_sum);

}  // namespace glint::metrics
