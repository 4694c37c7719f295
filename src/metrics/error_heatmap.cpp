#include "metrics/error_heatmap.h"

#include "core/error.h"
#include "metrics/channel_planes.h"

#include <algorithm>
#include <cmath>

namespace glint::metrics {
namespace {

std::uint8_t to_byte(double unit) { return static_cast<std::uint8_t>(std::floor(std::clamp(unit, 0.0, 1.0) * 255.0 + 0.5)); }

}  // namespace

glm::u8vec4 heat_ramp(double t) {
  const double s = 3.0 * std::clamp(t, 0.0, 1.0);
  return {to_byte(s), to_byte(s - 1.0), to_byte(s - 2.0), 255};
}

ImageRgba8 luma_error_heatmap(const ImageRgba8& test, const ImageRgba8& reference, const HeatmapOptions& options,
                              std::string_view test_name, std::string_view reference_name) {
  if (!(options.full_scale > 0.0)) fail("heat map: full scale must be > 0, got {}", options.full_scale);
  require_same_size(test, reference, test_name, reference_name);
  const Plane test_luma = luma_plane(test), reference_luma = luma_plane(reference);
  ImageRgba8 heatmap(test.width, test.height);
  for (std::size_t i = 0; i < heatmap.pixels.size(); ++i)
    heatmap.pixels[i] = heat_ramp(std::abs(test_luma.pixels[i] - reference_luma.pixels[i]) / options.full_scale);
  return heatmap;
}

}  // namespace glint::metrics
