#include "metrics/rmse_psnr.h"

#include <cmath>
#include <cstdint>
#include <limits>

namespace glint::metrics {

double psnr_from_rmse(double rmse, double peak) {
  if (rmse == 0.0) return std::numeric_limits<double>::infinity();
  return 20.0 * std::log10(peak / rmse);
}

RmsePsnr rmse_psnr(const ImageRgba8& test, const ImageRgba8& reference, std::string_view test_name,
                   std::string_view reference_name) {
  require_same_size(test, reference, test_name, reference_name);
  // Squared 8-bit differences are integers below 2^16, so 64-bit sums are exact and the result
  // does not depend on summation order.
  std::array<std::uint64_t, 3> squared_sums{};
  for (std::size_t i = 0; i < test.pixels.size(); ++i)
    for (glm::length_t c = 0; c < 3; ++c) {
      const int difference = int(test.pixels[i][c]) - int(reference.pixels[i][c]);
      squared_sums[static_cast<std::size_t>(c)] += static_cast<std::uint64_t>(difference * difference);
    }
  const double pixel_count = static_cast<double>(test.pixels.size());
  RmsePsnr result;
  std::uint64_t total = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    result.channel_rmse[c] = std::sqrt(static_cast<double>(squared_sums[c]) / pixel_count);
    result.channel_psnr[c] = psnr_from_rmse(result.channel_rmse[c]);
    total += squared_sums[c];
  }
  result.rmse = std::sqrt(static_cast<double>(total) / (3.0 * pixel_count));
  result.psnr = psnr_from_rmse(result.rmse);
  return result;
}

}  // namespace glint::metrics
