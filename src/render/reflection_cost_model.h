#pragma once
// What SSR and rays cost on this machine, for `--reflections auto` (tile_classification.h): ms per
// reflective pixel SSR marched and ms per traced ray (ray list + trace + hit shading), per backend.
// It starts from a prior for the backend's kind (device or host tracing), is calibrated by the first
// frames' timers (every tile of the first frame runs SSR + rays, which measures both) and follows
// every later frame's timers as an exponential moving average. Frames arrive frames late
// (app/frame_loop.h reads timers once the GPU is past them); the classifier uses what is known.
#include "render/tile_classification.h"

#include <cstdint>
#include <optional>

namespace glint::render {

// One frame's measurement: a stage's time and the work it did; a stage that did little (fewer than
// kMinCostSampleWork pixels or rays) is not used, its time being mostly fixed overhead.
struct CostSample {
  double ssr_ms = 0.0;
  std::uint32_t ssr_pixels = 0;  // reflective pixels SSR marched
  double ray_ms = 0.0;           // ray list + trace + hit shading
  std::uint32_t rays = 0;
};
inline constexpr std::uint32_t kMinCostSampleWork = 256;

// The prior before any frame was measured: rays on a GPU backend cost a few SSR pixels, on a CPU
// backend (llvmpipe + TBB) tens of them.
ReflectionCosts prior_reflection_costs(bool device_tracing);

class ReflectionCostModel {
public:
  // `fixed`: costs that never change (tests, and runs that want decisions independent of timing noise).
  explicit ReflectionCostModel(ReflectionCosts prior, std::optional<ReflectionCosts> fixed = std::nullopt);

  // Folds one frame in: the first usable sample of a stage replaces the prior (calibration), later
  // ones move the estimate by `kSmoothing` of their difference.
  void observe(const CostSample& sample);
  ReflectionCosts costs() const { return fixed_ ? *fixed_ : costs_; }
  bool calibrated() const { return fixed_ || (ssr_samples_ > 0 && ray_samples_ > 0); }
  std::uint64_t ssr_samples() const { return ssr_samples_; }
  std::uint64_t ray_samples() const { return ray_samples_; }

  static constexpr double kSmoothing = 0.2;

private:
  ReflectionCosts costs_;
  std::optional<ReflectionCosts> fixed_;
  std::uint64_t ssr_samples_ = 0, ray_samples_ = 0;
};

}  // namespace glint::render
