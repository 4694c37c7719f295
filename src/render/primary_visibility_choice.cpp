#include "render/primary_visibility_choice.h"

#include "gl/gl_renderer.h"
#include "gl/gl_work_time.h"

#include <algorithm>
#include <limits>

namespace glint::render {

PrimaryVisibility faster_primary_visibility(double raster_ms, double compute_ms) {
  return compute_ms * kComputeRasterMargin < raster_ms ? PrimaryVisibility::compute : PrimaryVisibility::raster;
}

std::optional<PrimaryVisibilityChoice> untimed_primary_visibility(std::string_view gl_renderer) {
  if (software_gl_renderer(gl_renderer)) return PrimaryVisibilityChoice{};
  return std::nullopt;
}

PrimaryVisibilityChoice choose_primary_visibility(const std::function<void()>& id_draw,
                                                  const std::function<void()>& compute_raster) {
  double raster_ms = std::numeric_limits<double>::infinity();
  double compute_ms = raster_ms;
  // Alternating, so that a clock ramping up or a neighbour's load during the measurement weighs on both.
  for (int run = 0; run < kPrimaryVisibilityTimedRuns; ++run) {
    raster_ms = std::min(raster_ms, time_gl_work_ms(id_draw));
    compute_ms = std::min(compute_ms, time_gl_work_ms(compute_raster));
  }
  return {faster_primary_visibility(raster_ms, compute_ms), raster_ms, compute_ms};
}

}  // namespace glint::render
