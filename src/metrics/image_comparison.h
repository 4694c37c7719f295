#pragma once
// Everything `glint compare` reports about a test image against a reference, in one call: the
// paper's colour buckets, SSIM on luma and per channel, RMSE and PSNR. Formulas: the headers of
// each metric and docs/metrics.md.
#include "core/image.h"
#include "metrics/color_buckets.h"
#include "metrics/image_size_check.h"
#include "metrics/rmse_psnr.h"
#include "metrics/ssim.h"

#include <string_view>

namespace glint::metrics {

struct ImageComparison {
  int width = 0;
  int height = 0;
  ColorBucketSimilarity buckets;
  ColourSsim ssim;
  RmsePsnr error;
};

// Checks the sizes first, so a mismatch is one error naming both images and sizes. Images smaller
// than the SSIM window (11x11) are an error too.
ImageComparison compare_images(const ImageRgba8& test, const ImageRgba8& reference,
                               std::string_view test_name = kDefaultTestName,
                               std::string_view reference_name = kDefaultReferenceName);

}  // namespace glint::metrics
