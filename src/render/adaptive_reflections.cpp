#include "render/adaptive_reflections.h"

#include "core/error.h"

#include <cmath>
#include <limits>

namespace glint::render {
namespace {

// A camera that moved by more than a screen since the last frame shows another view: what SSR did
// there says nothing about this frame (a cut, or frames far apart along the walkthrough).
constexpr float kCutMotion = 1.0f;

}  // namespace

void AdaptiveSettings::validate() const {
  budget.validate();
  if (!(max_unreflected_fraction >= 0.0f && max_unreflected_fraction <= 1.0f))
    fail("reflections auto: the quality target {} (largest unreflected fraction of a tile) must be in [0, 1]",
         max_unreflected_fraction);
}

AdaptiveReflections::AdaptiveReflections(int width, int height, const AdaptiveSettings& settings, bool device_tracing,
                                         float scene_diagonal)
    : settings_(settings),
      scene_diagonal_(scene_diagonal),
      pass_(width, height),
      costs_(prior_reflection_costs(device_tracing), settings.fixed_costs),
      governor_(settings.budget) {
  settings_.validate();
}

void AdaptiveReflections::classify(const TileClassifyInputs& inputs, const CameraState& camera, std::size_t slot) {
  // The newest frame whose tiles the GPU has finished (CPU backends: usually the last one, since the
  // CPU waited for its ray list; GPU backends: a frame or two back).
  for (std::uint64_t back = 1; back < kFramesInFlight && back <= frames_; ++back) {
    const std::uint64_t frame = frames_ - back;
    const auto frame_slot = static_cast<std::size_t>(frame % kFramesInFlight);
    if (slot_frame_[frame_slot] != frame || (newest_read_ && *newest_read_ >= frame)) break;
    if (!pass_.readback_ready(frame_slot)) continue;
    if (std::optional<TileFrameReadback> tiles = pass_.take(frame_slot, /*wait=*/false)) {
      newest_tiles_ = std::move(tiles->tiles);
      newest_read_ = frame;
      break;
    }
  }

  const float motion = previous_camera_ ? camera_motion(*previous_camera_, camera, scene_diagonal_) : 0.0f;
  if (motion > kCutMotion) pass_.reset_history();
  Decision decision;
  decision.budget_factor = settings_.budget.limited() ? governor_.next(motion) : 1.0f;
  decision.costs = costs_.costs();
  ThresholdInputs thresholds_in;
  thresholds_in.costs = decision.costs;
  thresholds_in.max_unreflected_fraction = settings_.max_unreflected_fraction;
  if (settings_.budget.rays)
    decision.ray_budget = static_cast<double>(*settings_.budget.rays);
  else if (settings_.budget.ms)
    decision.ray_budget = rays_within_ms(newest_tiles_, thresholds_in, *settings_.budget.ms);
  if (decision.ray_budget) decision.ray_budget = std::floor(*decision.ray_budget * decision.budget_factor);
  thresholds_in.ray_budget = decision.ray_budget;
  decision.thresholds = choose_tile_thresholds(newest_tiles_, thresholds_in);
  max_rays_ = decision.ray_budget
                  ? static_cast<std::uint32_t>(std::min<double>(*decision.ray_budget, 0x7fffffff))
                  : std::numeric_limits<std::uint32_t>::max();

  // Start-up calibration of the cost lines (reflection_cost_model.h): frame 0 runs SSR + rays on
  // every reflective tile (none is known yet), frame 1 rays only, so both stages are measured at
  // very different amounts of work.
  const bool calibrating = frames_ == 1 && !costs_.fixed();
  pass_.run(inputs, decision.thresholds, calibrating ? std::optional(TileClass::rt_only) : std::nullopt);
  decisions_[slot] = decision;
  slot_frame_[slot] = frames_;
  previous_camera_ = camera;
  ++frames_;
}

void AdaptiveReflections::finish_frame(std::size_t slot) { pass_.request_readback(slot); }

std::optional<AdaptiveFrameStats> AdaptiveReflections::take_stats(std::size_t slot, bool wait) {
  const std::optional<TileFrameReadback> tiles = pass_.take(slot, wait);
  if (!tiles) return std::nullopt;
  AdaptiveFrameStats stats;
  for (std::size_t c = 0; c < kTileClassCount; ++c) {
    stats.class_tiles[c] = tiles->block.class_tiles[c];
    stats.class_pixels[c] = tiles->block.class_pixels[c];
    stats.reflective_pixels += tiles->block.class_pixels[c];
  }
  stats.rays_wanted = tiles->block.rays_wanted;
  const Decision& decision = decisions_[slot];
  stats.ray_budget = decision.ray_budget;
  stats.budget_factor = decision.budget_factor;
  stats.thresholds = decision.thresholds;
  stats.costs = decision.costs;
  return stats;
}

}  // namespace glint::render
