#pragma once
// Metrics on linear HDR colour (EXR files of `glint render --format exr`), beside the 8-bit metrics
// of the tone-mapped pictures: an error in linear radiance counts the same in a dark corner and in a
// highlight, which the sRGB-encoded 8-bit values do not. Over N pixels, for c in R, G, B:
//   MSE_c = (1/N) sum (test_c - ref_c)^2,  RMSE_c = sqrt(MSE_c),  RMSE = sqrt((MSE_R + MSE_G + MSE_B) / 3)
//   peak  = the reference's largest R, G or B value
//   PSNR  = 20 log10(peak / RMSE) dB (+inf for RMSE 0; per channel likewise, with the same peak)
//   SSIM  on relative luminance Y = 0.2126 R + 0.7152 G + 0.0722 B of the linear values, with the
//         8-bit SSIM's window and constants but L = the reference's largest Y (1 for a black reference)
// HDR peaks (a light, a highlight) raise `peak` and L, so PSNR and SSIM read kinder where an image
// holds a few very bright pixels; the RMSE is in the images' own units. Everything in double.
#include "core/image.h"
#include "metrics/channel_planes.h"
#include "metrics/image_size_check.h"

#include <array>
#include <string_view>

namespace glint::metrics {

struct LinearComparison {
  int width = 0;
  int height = 0;
  std::array<double, 3> channel_rmse{};  // R, G, B
  double rmse = 0.0;
  double peak = 0.0;                     // the reference's largest R, G or B value
  std::array<double, 3> channel_psnr{};  // dB against `peak`
  double psnr = 0.0;
  double ssim_luminance = 0.0;           // SSIM on Y, L = the reference's largest Y
  double luminance_peak = 0.0;           // that L
};

// Rec. 709 relative luminance of linear colour, per pixel.
Plane luminance_plane(const ImageRgbaF& image);

// glint::Error naming `name` and the first pixel whose R, G or B is not finite (NaN, infinity):
// the linear metrics would be NaN.
void require_finite(const ImageRgbaF& image, std::string_view name = kDefaultTestName);

// Sizes checked first (one error naming both); images smaller than the SSIM window are an error.
LinearComparison compare_linear_images(const ImageRgbaF& test, const ImageRgbaF& reference,
                                       std::string_view test_name = kDefaultTestName,
                                       std::string_view reference_name = kDefaultReferenceName);

}  // namespace glint::metrics
