#pragma once
// Root-mean-square error and peak signal-to-noise ratio on the 0..255 values of the files (alpha
// ignored). Over N pixels,
//   MSE_c   = (1/N) sum (test_c - ref_c)^2        for c in R, G, B
//   MSE     = (MSE_R + MSE_G + MSE_B) / 3          (all 3N values together)
//   RMSE    = sqrt(MSE),  RMSE_c = sqrt(MSE_c)
//   PSNR    = 20 log10(255 / RMSE) dB, +infinity when RMSE = 0 (identical images); likewise per channel.
// PSNR is only a rescaled RMSE; both are reported because papers quote one or the other.
#include "core/image.h"
#include "metrics/image_size_check.h"

#include <array>
#include <string_view>

namespace glint::metrics {

struct RmsePsnr {
  std::array<double, 3> channel_rmse{};  // R, G, B
  double rmse = 0.0;                     // over all three channels
  std::array<double, 3> channel_psnr{};  // dB, +inf where the channel is identical
  double psnr = 0.0;                     // dB, +inf for identical images
};

RmsePsnr rmse_psnr(const ImageRgba8& test, const ImageRgba8& reference, std::string_view test_name = kDefaultTestName,
                   std::string_view reference_name = kDefaultReferenceName);

// 20 log10(peak / rmse), +infinity for rmse = 0.
double psnr_from_rmse(double rmse, double peak = 255.0);

}  // namespace glint::metrics
