#include "metrics/flicker.h"

#include "core/error.h"
#include "metrics/image_size_check.h"

#include <cmath>

namespace glint::metrics {

void FlickerMeter::add(const ImageRgba8& frame, std::string_view name) {
  if (frame.width <= 0 || frame.height <= 0) fail("flicker: {} is empty", name);
  Plane luma = luma_plane(frame);
  const double pixels = static_cast<double>(luma.pixels.size());
  double luma_total = 0.0;
  for (const double value : luma.pixels) luma_total += value;
  if (frames_ > 0) {
    require_same_size(luma, previous_, name, "the frame before it");
    double change_total = 0.0;
    for (std::size_t i = 0; i < luma.pixels.size(); ++i) change_total += std::abs(luma.pixels[i] - previous_.pixels[i]);
    change_sum_ += change_total / pixels;
  }
  luma_sum_ += luma_total / pixels;
  previous_ = std::move(luma);
  ++frames_;
}

Flicker FlickerMeter::result() const {
  if (frames_ < 2) fail("flicker: needs at least two frames, got {}", frames_);
  Flicker flicker;
  flicker.frames = frames_;
  flicker.mean_abs_change = change_sum_ / static_cast<double>(frames_ - 1);
  flicker.mean_luma = luma_sum_ / static_cast<double>(frames_);
  flicker.ratio = flicker.mean_luma > 0.0 ? flicker.mean_abs_change / flicker.mean_luma : 0.0;
  return flicker;
}

Flicker measure_flicker(const std::vector<ImageRgba8>& frames) {
  FlickerMeter meter;
  for (const ImageRgba8& frame : frames) meter.add(frame);
  return meter.result();
}

}  // namespace glint::metrics
