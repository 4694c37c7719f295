#include "metrics/linear_metrics.h"

#include "core/error.h"
#include "metrics/rmse_psnr.h"
#include "metrics/ssim.h"

#include <algorithm>
#include <cmath>

namespace glint::metrics {

Plane luminance_plane(const ImageRgbaF& image) {
  Plane plane(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const glm::vec4& p = image.pixels[i];
    plane.pixels[i] = kLumaRed * double(p.x) + kLumaGreen * double(p.y) + kLumaBlue * double(p.z);
  }
  return plane;
}

void require_finite(const ImageRgbaF& image, std::string_view name) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec4& p = image.at(x, y);
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        fail("'{}': pixel ({}, {}) is not a finite colour ({}, {}, {}); linear metrics need finite values", name, x, y,
             p.x, p.y, p.z);
    }
}

LinearComparison compare_linear_images(const ImageRgbaF& test, const ImageRgbaF& reference,
                                       std::string_view test_name, std::string_view reference_name) {
  require_same_size(test, reference, test_name, reference_name);
  LinearComparison result;
  result.width = test.width;
  result.height = test.height;
  std::array<double, 3> squared_sums{};
  for (std::size_t i = 0; i < test.pixels.size(); ++i)
    for (glm::length_t c = 0; c < 3; ++c) {
      const double difference = double(test.pixels[i][c]) - double(reference.pixels[i][c]);
      squared_sums[static_cast<std::size_t>(c)] += difference * difference;
      result.peak = std::max(result.peak, double(reference.pixels[i][c]));
    }
  const double pixel_count = static_cast<double>(test.pixels.size());
  for (std::size_t c = 0; c < 3; ++c) {
    result.channel_rmse[c] = std::sqrt(squared_sums[c] / pixel_count);
    result.channel_psnr[c] = psnr_from_rmse(result.channel_rmse[c], result.peak);
  }
  result.rmse = std::sqrt((squared_sums[0] + squared_sums[1] + squared_sums[2]) / (3.0 * pixel_count));
  result.psnr = psnr_from_rmse(result.rmse, result.peak);

  const Plane test_luminance = luminance_plane(test), reference_luminance = luminance_plane(reference);
  const double luminance_peak = *std::max_element(reference_luminance.pixels.begin(), reference_luminance.pixels.end());
  result.luminance_peak = luminance_peak > 0.0 ? luminance_peak : 1.0;
  SsimOptions options;
  options.dynamic_range = result.luminance_peak;
  result.ssim_luminance = ssim(test_luminance, reference_luminance, options, test_name, reference_name).mean;
  return result;
}

}  // namespace glint::metrics
