#pragma once
// A picture of where two images differ: per pixel, the absolute difference of Rec. 709 luma
//   d = |Y'(test) - Y'(ref)|, 0..255   (Y' as in channel_planes.h)
// mapped through a fixed "hot" ramp with t = min(d / full_scale, 1):
//   t = 0 black, 1/3 red, 2/3 yellow, 1 white, linear in between, i.e.
//   R = clamp(3t, 0, 1), G = clamp(3t - 1, 0, 1), B = clamp(3t - 2, 0, 1), times 255, rounded.
// The ramp's brightness grows with the error, so it also reads in greyscale, and a fixed scale (not
// the image's own maximum) keeps heat maps of different frames comparable. Alpha is 255.
// Luma difference rather than 1 - SSIM because it is defined at every pixel (SSIM's valid map is
// 10 pixels smaller) and points at the exact pixels that differ.
#include "core/image.h"
#include "metrics/image_size_check.h"

#include <string_view>

namespace glint::metrics {

struct HeatmapOptions {
  double full_scale = 64.0;  // luma difference (0..255) that maps to white; must be > 0
};

// Same size as the inputs. Throws a glint::Error naming both images when their sizes differ.
ImageRgba8 luma_error_heatmap(const ImageRgba8& test, const ImageRgba8& reference, const HeatmapOptions& options = {},
                              std::string_view test_name = kDefaultTestName,
                              std::string_view reference_name = kDefaultReferenceName);

// The ramp alone: t in [0, 1] (clamped) to an opaque colour.
glm::u8vec4 heat_ramp(double t);

}  // namespace glint::metrics
