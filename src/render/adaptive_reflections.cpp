#include "render/adaptive_reflections.h"

#include "core/error.h"

#include <cmath>
#include <limits>

namespace glint::render {
namespace {

// The start-up calibration's frames (begin_frame).
constexpr std::uint64_t kCalibrationFrames = 3;

// A camera that moved by more than a screen since the last frame shows another view: what SSR did
// there says nothing about this frame (a cut, or frames far apart along the walkthrough).
constexpr float kCutMotion = 1.0f;

// Every reflective tile is known and SSR alone reflects it within the quality target.
bool ssr_only_everywhere(std::span<const TileEvidence> tiles, const TileThresholds& thresholds) {
  bool any = false;
  for (const TileEvidence& tile : tiles) {
    if (tile.reflective == 0) continue;
    if (!known_enough(tile, thresholds) || classify_tile(tile, thresholds) != TileClass::ssr_only) return false;
    any = true;
  }
  return any;
}

// A whole-frame path is left before its re-check only when the model finds it this much dearer than
// the cheapest path: timing noise alone should not send it back to per-tile decisions every few frames.
constexpr double kLeaveMargin = 1.1;

double cost_of(const ReflectionPathCosts& costs, ReflectionPath path) {
  switch (path) {
    case ReflectionPath::all_rays: return costs.all_rays_ms;
    case ReflectionPath::all_ssr: return costs.all_ssr_ms.value_or(std::numeric_limits<double>::infinity());
    case ReflectionPath::per_tile: break;
  }
  return costs.per_tile_ms;
}

}  // namespace

void AdaptiveSettings::validate() const {
  budget.validate();
  if (!(max_unreflected_fraction >= 0.0f && max_unreflected_fraction <= 1.0f))
    fail("reflections auto: the quality target {} (largest unreflected fraction of a tile) must be in [0, 1]",
         max_unreflected_fraction);
  if (recheck_frames == 0) fail("reflections auto: the re-check period must be at least 1 frame");
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

void AdaptiveReflections::read_newest_tiles() {
  // The newest per-tile frame whose tiles the GPU has finished (CPU backends: usually the last one,
  // since the CPU waited for its ray list; GPU backends: a frame or two back).
  for (std::uint64_t back = 1; back < kFramesInFlight && back <= frames_; ++back) {
    const std::uint64_t frame = frames_ - back;
    const auto frame_slot = static_cast<std::size_t>(frame % kFramesInFlight);
    if (slot_frame_[frame_slot] != frame || (newest_read_ && *newest_read_ >= frame)) break;
    if (decisions_[frame_slot].path != ReflectionPath::per_tile) continue;  // nothing classified
    if (!pass_.readback_ready(frame_slot)) continue;
    if (std::optional<TileFrameReadback> tiles = pass_.take(frame_slot, /*wait=*/false)) {
      newest_tiles_ = std::move(tiles->tiles);
      newest_read_ = frame;
      break;
    }
  }
}

ReflectionPath AdaptiveReflections::choose_path() {
  const std::uint64_t frame = frames_;
  ReflectionPath next = path_;
  // Whole-frame paths need measured costs (after the two calibration frames) and no budget.
  if (settings_.budget.limited() || (!costs_.fixed() && frame < kCalibrationFrames) || !costs_.measured()) {
    next = ReflectionPath::per_tile;
  } else {
    ThresholdInputs optimal;
    optimal.costs = costs_.costs();
    optimal.max_unreflected_fraction = settings_.max_unreflected_fraction;
    ReflectionPathInputs inputs;
    inputs.costs = costs_.stage_costs();
    inputs.thresholds = choose_tile_thresholds({}, optimal);
    inputs.tiles = newest_tiles_;
    inputs.reflective_pixels = newest_reflective_;
    inputs.ssr_suffices = path_ == ReflectionPath::all_ssr ? ssr_alone_within_target_
                                                           : ssr_only_everywhere(newest_tiles_, inputs.thresholds);
    const ReflectionPathCosts compared = compare_reflection_paths(inputs);
    const ReflectionPath cheapest = compared.cheapest;
    if (path_ == ReflectionPath::per_tile) {
      // Decide only from tiles that know what SSR did since the last reset.
      if (newest_read_ && *newest_read_ >= first_deciding_frame_) next = cheapest;
    } else if (cost_of(compared, path_) > kLeaveMargin * cost_of(compared, cheapest) ||
               frame - path_since_ >= settings_.recheck_frames ||
               (path_ == ReflectionPath::all_ssr && !ssr_alone_within_target_)) {
      next = ReflectionPath::per_tile;  // measure the skipped stage and SSR's failures again
    }
  }
  if (next != path_) {
    if (next == ReflectionPath::per_tile) {
      // The outcomes the classification keeps are as old as the whole-frame stretch: start afresh.
      pass_.reset_history();
      first_deciding_frame_ = frame + 1;
    }
    if (next == ReflectionPath::all_ssr) ssr_alone_within_target_ = true;
    path_ = next;
    path_since_ = frame;
  }
  return path_;
}

ReflectionPath AdaptiveReflections::begin_frame(const CameraState& camera, std::size_t slot, std::uint64_t ray_runs) {
  read_newest_tiles();
  const float motion = previous_camera_ ? camera_motion(*previous_camera_, camera, scene_diagonal_) : 0.0f;
  if (motion > kCutMotion) pass_.reset_history();
  Decision decision;
  decision.path = choose_path();
  decision.ray_run = decision.path == ReflectionPath::all_ssr ? std::nullopt : std::optional(ray_runs);
  decision.budget_factor = settings_.budget.limited() ? governor_.next(motion) : 1.0f;
  decision.costs = costs_.stage_costs();
  ThresholdInputs thresholds_in;
  thresholds_in.costs = decision.costs.marginal;
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
  // Start-up calibration of the cost lines (reflection_cost_model.h): frames 0 and 1 run SSR + rays on
  // every reflective tile (whatever the prior says; frame 0 is not measured: first dispatches, cold
  // caches), frame 2 rays only (SSR marches no pixel: its time is the pyramid and the dispatch
  // alone), so both stages are measured at very different amounts of work.
  if (!costs_.fixed() && frames_ < kCalibrationFrames)
    decision.forced = frames_ + 1 < kCalibrationFrames ? TileClass::ssr_fallback : TileClass::rt_only;
  decisions_[slot] = decision;
  slot_frame_[slot] = frames_;
  slot_ = slot;
  previous_camera_ = camera;
  ++frames_;
  return decision.path;
}

void AdaptiveReflections::classify(const TileClassifyInputs& inputs) {
  const Decision& decision = decisions_[slot_];
  if (decision.path != ReflectionPath::per_tile) fail("reflections auto: classify() on a whole-frame path");
  pass_.run(inputs, decision.thresholds, decision.forced);
}

void AdaptiveReflections::observe(const CostSample& sample) {
  // Frame 0 (the first observed: frames come back in order) pays first dispatches and cold caches.
  if (observed_++ > 0) costs_.observe(sample);
}

void AdaptiveReflections::finish_frame(std::size_t slot) {
  if (decisions_[slot].path == ReflectionPath::per_tile) pass_.request_readback(slot);
}

std::optional<AdaptiveFrameStats> AdaptiveReflections::take_stats(std::size_t slot, bool wait,
                                                                  const std::optional<SsrCounts>& ssr,
                                                                  std::optional<std::uint32_t> traced_reflective) {
  const Decision& decision = decisions_[slot];
  AdaptiveFrameStats stats;
  stats.path = decision.path;
  if (decision.path == ReflectionPath::per_tile) {
    const std::optional<TileFrameReadback> tiles = pass_.take(slot, wait);
    if (!tiles) return std::nullopt;
    for (std::size_t c = 0; c < kTileClassCount; ++c) {
      stats.class_tiles[c] = tiles->block.class_tiles[c];
      stats.class_pixels[c] = tiles->block.class_pixels[c];
      stats.reflective_pixels += tiles->block.class_pixels[c];
    }
    stats.rays_wanted = tiles->block.rays_wanted;
  } else if (decision.path == ReflectionPath::all_rays) {
    stats.reflective_pixels = traced_reflective.value_or(0);  // the ray list listed every one
    stats.rays_wanted = stats.reflective_pixels;
  } else {
    stats.reflective_pixels = ssr ? ssr->reflective : 0;
  }
  stats.ray_budget = decision.ray_budget;
  stats.budget_factor = decision.budget_factor;
  stats.thresholds = decision.thresholds;
  stats.costs = decision.costs;

  // What the next decisions re-check the path with.
  const std::uint64_t frame = slot_frame_[slot];
  if (!newest_counted_ || frame > *newest_counted_) {
    newest_counted_ = frame;
    newest_reflective_ = stats.reflective_pixels;
    if (decision.path == ReflectionPath::all_ssr && path_ == ReflectionPath::all_ssr && frame >= path_since_ && ssr)
      ssr_alone_within_target_ = static_cast<double>(ssr->failed) <=
                                 static_cast<double>(settings_.max_unreflected_fraction) * ssr->reflective;
  }
  return stats;
}

std::vector<TileClass> AdaptiveReflections::last_classes(const ImageRgbaF& albedo_reflectivity,
                                                         const ImageRgbaF& world_position) const {
  const ReflectionPath path = decisions_[slot_].path;
  if (path == ReflectionPath::per_tile) return pass_.read().classes;
  const TileClass whole = path == ReflectionPath::all_rays ? TileClass::rt_only : TileClass::ssr_only;
  std::vector<TileClass> classes(pass_.tile_count(), TileClass::none);
  for (int y = 0; y < world_position.height; ++y)
    for (int x = 0; x < world_position.width; ++x) {
      const int gl_y = world_position.height - 1 - y;  // tiles count from GL's bottom row
      const auto tile = static_cast<std::size_t>((gl_y / kReflectionTileSize) * pass_.tile_columns() +
                                                 x / kReflectionTileSize);
      if (world_position.at(x, y).w != 0.0f && albedo_reflectivity.at(x, y).w > 0.0f) classes[tile] = whole;
    }
  return classes;
}

}  // namespace glint::render
