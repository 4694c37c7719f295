#pragma once
// Flicker of an image sequence: how much the picture changes from frame to frame, relative to how
// bright it is. Over frames 0..n (n >= 1) of the same size, with Y' the Rec. 709 luma of the 8-bit
// values (metrics/channel_planes.h) and P the pixel count,
//   change  = (1/n) sum_{t=1..n} (1/P) sum_p |Y'_t(p) - Y'_{t-1}(p)|     mean absolute change, 0..255
//   luma    = (1/(n+1)) sum_{t=0..n} (1/P) sum_p Y'_t(p)                 mean luma, 0..255
//   flicker = change / luma                                             (0 when luma is 0)
// A still camera on a still scene should give 0: whatever remains is noise the renderer adds (a
// stochastic sampler, a denoiser's history settling). Along a moving camera it includes the real
// motion of the picture. `glint bench --experiment glossy` reports it (docs/bench.md).
#include "core/image.h"
#include "metrics/channel_planes.h"

#include <cstddef>
#include <string_view>
#include <vector>

namespace glint::metrics {

struct Flicker {
  double mean_abs_change = 0.0;  // 0..255
  double mean_luma = 0.0;        // 0..255
  double ratio = 0.0;            // mean_abs_change / mean_luma
  std::size_t frames = 0;
};

// Frames fed one at a time (only the last one's luma is kept).
class FlickerMeter {
public:
  // glint::Error when `frame` differs in size from the first (naming `name`) or is empty.
  void add(const ImageRgba8& frame, std::string_view name = "frame");
  std::size_t frames() const { return frames_; }
  // glint::Error with fewer than two frames.
  Flicker result() const;

private:
  Plane previous_;
  double change_sum_ = 0.0;  // sum over pairs of the per-pixel mean absolute change
  double luma_sum_ = 0.0;    // sum over frames of the mean luma
  std::size_t frames_ = 0;
};

Flicker measure_flicker(const std::vector<ImageRgba8>& frames);

}  // namespace glint::metrics
