#pragma once
// SSIM, the structural similarity index of Wang, Bovik, Sheikh and Simoncelli, "Image quality
// assessment: from error visibility to structural similarity", IEEE TIP 13(4), 2004, with the
// paper's constants: an 11x11 Gaussian window (sigma 1.5, normalised to sum 1), K1 = 0.01,
// K2 = 0.03, dynamic range L = 255. For every window position,
//   mu_x, mu_y          Gaussian-weighted means
//   sigma_x^2, sigma_y^2, sigma_xy   Gaussian-weighted (co)variances, E[xy] - mu_x mu_y
//   SSIM = ((2 mu_x mu_y + C1)(2 sigma_xy + C2)) / ((mu_x^2 + mu_y^2 + C1)(sigma_x^2 + sigma_y^2 + C2))
// with C1 = (K1 L)^2, C2 = (K2 L)^2, and the mean SSIM is the plain mean of that map.
//
// Borders: only windows that lie entirely inside the image are used (the 'valid' output of the
// authors' MATLAB ssim_index.m, filter2(..., 'valid')), so the map is (W - 10) x (H - 10) and no
// padding invents pixels. No downsampling is applied (the later ssim.m downsamples large images;
// that would change the numbers with the resolution, which a renderer comparison should not).
//
// The Gaussian is separable, so each of the five local moments is filtered as a horizontal then a
// vertical 11-tap pass, each pass parallel over rows (TBB). Everything is in double precision.
#include "metrics/channel_planes.h"
#include "metrics/image_size_check.h"

#include <array>
#include <string_view>
#include <vector>

namespace glint::metrics {

struct SsimOptions {
  int window_radius = 5;  // window side 2 * radius + 1 = 11
  double sigma = 1.5;
  double k1 = 0.01;
  double k2 = 0.03;
  double dynamic_range = 255.0;  // L
};

struct SsimResult {
  double mean = 0.0;  // mean of `map`
  Plane map;          // one value per valid window, (W - 2r) x (H - 2r); map.at(x, y) is the window
                      // whose top-left pixel is (x, y), i.e. centred on (x + r, y + r)
};

// The normalised 1-D Gaussian taps (2 * radius + 1 of them, summing to 1); the 2-D window is their
// outer product.
std::vector<double> ssim_gaussian_taps(const SsimOptions& options = {});

// SSIM of two planes of 0..L values. Throws a glint::Error when the sizes differ (naming both) or
// when the images are smaller than one window.
SsimResult ssim(const Plane& test, const Plane& reference, const SsimOptions& options = {},
                std::string_view test_name = kDefaultTestName,
                std::string_view reference_name = kDefaultReferenceName);

// SSIM on Rec. 709 luma and on each of R, G, B of two 8-bit images (alpha ignored).
struct ColourSsim {
  double luma = 0.0;
  std::array<double, 3> channel{};  // R, G, B
};
ColourSsim colour_ssim(const ImageRgba8& test, const ImageRgba8& reference, const SsimOptions& options = {},
                       std::string_view test_name = kDefaultTestName,
                       std::string_view reference_name = kDefaultReferenceName);

}  // namespace glint::metrics
