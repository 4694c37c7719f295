#pragma once
// What SSR and rays cost on this machine, for `--reflections auto` (tile_classification.h,
// reflection_path.h). Each stage's time is a line in its work: fixed + per_item x items.
//   SSR:           the "ssr" pass (depth pyramid + march) over the reflective pixels it marched;
//   rays:          ray list + trace + hit shading over the rays traced;
//   classification: the "classify" pass, fixed (one work group per tile, whatever it decides).
// The tile rule weighs the marginal costs (per SSR pixel, per ray: a tile's choice moves only
// those); the whole-frame choice (reflection_path.h) weighs the fixed parts too, since a frame that
// marches no SSR skips the pyramid and the march's dispatch, and one with no per-tile decision skips
// the classification.
// Each line is fitted over the frames by exponentially weighted least squares (so it follows the
// machine). A slope needs points spread along the work; once fitted it is kept while later frames
// all do about the same work (steady state), and the fixed part then follows their mean time. Start-up
// calibrates both lines: frames 0 and 1 run SSR + rays on every reflective tile (frame 0, cold, is
// not measured), frame 2 rays only (SSR marches no pixel: its time is the fixed part alone;
// AdaptiveReflections), two points far apart for both lines. Until a line has a slope, the cost is the stage's time over its items (a
// moving average, no fixed part: right at the work measured), and before any frame a prior for the
// backend's kind. Frames arrive frames late (app/frame_loop.h reads timers once the GPU is past them).
#include "render/tile_classification.h"

#include <cstdint>
#include <optional>

namespace glint::render {

// One frame's measurement: each stage's time and the work it did (0 ms: the stage did not run).
struct CostSample {
  double ssr_ms = 0.0;
  std::uint32_t ssr_pixels = 0;  // reflective pixels SSR marched
  double ray_ms = 0.0;           // ray list + trace + hit shading
  std::uint32_t rays = 0;
  double classify_ms = 0.0;      // the tile classification
};
// A stage that did fewer items is not used for the time-over-items average (its time is mostly fixed).
inline constexpr std::uint32_t kMinCostSampleWork = 256;

// A stage's time as a line in its work.
struct CostLine {
  double fixed_ms = 0.0;
  double per_item_ms = 0.0;
};

// Everything the whole-frame choice weighs (reflection_path.h).
struct ReflectionStageCosts {
  ReflectionCosts marginal;   // per SSR pixel, per ray: what the tile rule compares
  double ssr_fixed_ms = 0.0;  // any frame that runs SSR: the depth pyramid, the march's dispatch
  double ray_fixed_ms = 0.0;  // any frame that traces: ray list, trace and hit shading dispatches, fences
  double classify_ms = 0.0;   // any frame with per-tile decisions: the classification pass
};

// The prior before any frame was measured: rays on a GPU backend cost a few SSR pixels, on a CPU
// backend (llvmpipe + TBB) tens of them.
ReflectionCosts prior_reflection_costs(bool device_tracing);

// ms = fixed + slope x items, fitted to weighted points whose weights decay by kDecay per point.
class AffineCostFit {
public:
  void add(double items, double ms);
  // nullopt until the points once spread enough along the items to tell a slope from noise (their
  // weighted deviation at least a tenth of their mean and at least kMinCostSampleWork). From then on
  // the newest such slope (>= 0), with the fixed part through the points' weighted mean (where that
  // part would be negative: no fixed part, the slope through the origin and the mean).
  std::optional<CostLine> line() const;
  bool empty() const { return w_ <= 0.0; }

  static constexpr double kDecay = 0.9;

private:
  double w_ = 0.0, n_ = 0.0, t_ = 0.0, nn_ = 0.0, nt_ = 0.0;
  std::optional<double> slope_;  // the last slope the points' spread allowed
};

class ReflectionCostModel {
public:
  // `fixed`: costs that never change (tests, and runs that want decisions free of timing noise).
  explicit ReflectionCostModel(ReflectionCosts prior, std::optional<ReflectionStageCosts> fixed = std::nullopt);

  // Folds one frame in (a stage that did not run, 0 ms, is left out).
  void observe(const CostSample& sample);
  // The marginal costs (the tile rule's).
  ReflectionCosts costs() const;
  // The marginal costs and the fixed parts (0 while a stage has no fitted line, or was never timed).
  ReflectionStageCosts stage_costs() const;
  // Both SSR and rays have been timed at least once (or the costs are fixed): stage_costs() is measured,
  // not the prior.
  bool measured() const { return fixed_ || (!ssr_fit_.empty() && !ray_fit_.empty()); }
  bool fixed() const { return fixed_.has_value(); }
  std::uint64_t ssr_samples() const { return ssr_samples_; }
  std::uint64_t ray_samples() const { return ray_samples_; }

  static constexpr double kSmoothing = 0.2;  // the moving averages' weight of a new frame

private:
  ReflectionCosts average_;  // time over items, a moving average (the prior before any frame)
  std::optional<ReflectionStageCosts> fixed_;
  AffineCostFit ssr_fit_, ray_fit_;
  double classify_ms_ = 0.0;
  std::uint64_t ssr_samples_ = 0, ray_samples_ = 0, classify_samples_ = 0;
};

}  // namespace glint::render
