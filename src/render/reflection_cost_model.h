#pragma once
// What SSR and rays cost on this machine, for `--reflections auto` (tile_classification.h): the
// marginal ms per reflective pixel SSR marches and per traced ray (ray list + trace + hit shading).
// Marginal, because each stage also has a fixed part (a dispatch, a fence, a GPU that needs many
// rays to fill it) that a tile's choice does not change: each stage's time is fitted as
// fixed + per_item x items over the frames (exponentially weighted least squares, so it follows the
// machine), and the slope is the cost. Start-up calibrates it: the first frame runs SSR + rays on
// every reflective tile, the second rays only (AdaptiveReflections), two points far apart for both
// lines. Until a line is known (or while its points are too close together to fit) the cost is the
// stage's time over its items (a moving average), and before any frame a prior for the backend's
// kind. Frames arrive frames late (app/frame_loop.h reads timers once the GPU is past them).
#include "render/tile_classification.h"

#include <cstdint>
#include <optional>

namespace glint::render {

// One frame's measurement: a stage's time and the work it did.
struct CostSample {
  double ssr_ms = 0.0;
  std::uint32_t ssr_pixels = 0;  // reflective pixels SSR marched
  double ray_ms = 0.0;           // ray list + trace + hit shading
  std::uint32_t rays = 0;
};
// A stage that did fewer items is not used for the time-over-items average (its time is mostly fixed).
inline constexpr std::uint32_t kMinCostSampleWork = 256;

// The prior before any frame was measured: rays on a GPU backend cost a few SSR pixels, on a CPU
// backend (llvmpipe + TBB) tens of them.
ReflectionCosts prior_reflection_costs(bool device_tracing);

// ms = fixed + slope x items, fitted to weighted points whose weights decay by kDecay per point.
class AffineCostFit {
public:
  void add(double items, double ms);
  // The slope (>= 0) once the points spread enough along the items to tell it from noise: their
  // weighted deviation at least a tenth of their mean and at least kMinCostSampleWork.
  std::optional<double> slope() const;

  static constexpr double kDecay = 0.9;

private:
  double w_ = 0.0, n_ = 0.0, t_ = 0.0, nn_ = 0.0, nt_ = 0.0;
};

class ReflectionCostModel {
public:
  // `fixed`: costs that never change (tests, and runs that want decisions free of timing noise).
  explicit ReflectionCostModel(ReflectionCosts prior, std::optional<ReflectionCosts> fixed = std::nullopt);

  // Folds one frame in (a stage that did not run, 0 ms, is left out).
  void observe(const CostSample& sample);
  ReflectionCosts costs() const;
  bool fixed() const { return fixed_.has_value(); }
  std::uint64_t ssr_samples() const { return ssr_samples_; }
  std::uint64_t ray_samples() const { return ray_samples_; }

  static constexpr double kSmoothing = 0.2;  // the time-over-items average's weight of a new frame

private:
  ReflectionCosts average_;  // time over items, a moving average (the prior before any frame)
  std::optional<ReflectionCosts> fixed_;
  AffineCostFit ssr_fit_, ray_fit_;
  std::uint64_t ssr_samples_ = 0, ray_samples_ = 0;
};

}  // namespace glint::render
