#include "metrics/image_comparison.h"

namespace glint::metrics {

ImageComparison compare_images(const ImageRgba8& test, const ImageRgba8& reference, std::string_view test_name,
                               std::string_view reference_name) {
  require_same_size(test, reference, test_name, reference_name);
  ImageComparison result;
  result.width = test.width;
  result.height = test.height;
  result.ssim = colour_ssim(test, reference, SsimOptions{}, test_name, reference_name);
  result.buckets = color_bucket_similarity(test, reference, test_name, reference_name);
  result.error = rmse_psnr(test, reference, test_name, reference_name);
  return result;
}

}  // namespace glint::metrics
