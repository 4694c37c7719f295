#pragma once
// AdaptiveReflections: the host half of `--reflections auto` (docs/hybrid.md "auto"). Per frame,
// before SSR, begin_frame() chooses the frame's path (reflection_path.h): per-tile decisions, or one
// method for the whole frame with no per-tile work (all rays: no classification, depth pyramid or
// SSR; all SSR: no classification or rays). A per-tile frame then gets the budget for this frame
// (ReflectionBudget scaled by the camera's motion), the thresholds of the tile rule from the newest
// tiles the host has read back and the cost model (tile_classification.h, reflection_cost_model.h),
// and classify() runs TileClassifyPass on the GPU, which hands SSR and the ray list their tile lists.
// After the frame its timers feed the cost model (observe(), called by FramePipeline::observe when
// app/frame_loop.cpp reads the frame) and its counts the path's re-check (take_stats()).
//
// The path is re-checked every frame on the host from the newest costs and counts (a frame on a
// whole-frame path still measures its own stage and the reflective pixels); a whole-frame path is
// left for per-tile decisions when that check prefers another path, when SSR alone fails on more
// than the quality target (all SSR), or every recheck_frames frames, so that the stage the path
// skips is measured again and the tiles learn SSR's failure rates again. Whole-frame paths need the
// costs measured (the two calibration frames) and no budget (a budget is a per-tile trade-off).
#include "core/image.h"
#include "gl/gpu_timer.h"
#include "render/reflection_budget.h"
#include "render/reflection_cost_model.h"
#include "render/reflection_path.h"
#include "render/ssr_pass.h"
#include "render/tile_classify_pass.h"

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace glint::render {

struct AdaptiveSettings {
  ReflectionBudget budget;
  // The quality target (ThresholdInputs::max_unreflected_fraction).
  float max_unreflected_fraction = 0.0f;
  // Costs that never change instead of the measured ones (tests; decisions free of timing noise).
  std::optional<ReflectionStageCosts> fixed_costs;
  // A whole-frame path goes back to per-tile decisions (fresh SSR timings and failure rates) at
  // least this often, in frames (> 0).
  std::uint32_t recheck_frames = 120;

  void validate() const;  // glint::Error naming the bad field
};

// What auto decided for one frame (timings.csv's adaptive columns).
struct AdaptiveFrameStats {
  ReflectionPath path = ReflectionPath::per_tile;
  // Per TileClass; all 0 on a whole-frame path (nothing was classified).
  std::array<std::uint32_t, kTileClassCount> class_tiles{};
  std::array<std::uint32_t, kTileClassCount> class_pixels{};  // reflective pixels per class
  std::uint32_t reflective_pixels = 0;                        // all classes (whole frame: SSR's or the ray list's count)
  std::uint32_t rays_wanted = 0;                              // before the budget cut
  std::optional<double> ray_budget;                           // this frame's, after motion
  float budget_factor = 1.0f;                                 // motion's share of the budget
  TileThresholds thresholds;
  ReflectionStageCosts costs;  // the cost model's estimate the decisions came from
};

class AdaptiveReflections {
public:
  // `device_tracing`: the backend traces on the GPU (its prior costs); `scene_diagonal` scales the
  // camera's travel (camera_motion).
  AdaptiveReflections(int width, int height, const AdaptiveSettings& settings, bool device_tracing,
                      float scene_diagonal);

  // Chooses frame `slot`'s path (slot = frame % kFramesInFlight) and, for per-tile frames, its budget
  // and thresholds. `ray_runs`: the ray-traced runs before this frame (the frame's run, unless it
  // traces nothing).
  ReflectionPath begin_frame(const CameraState& camera, std::size_t slot, std::uint64_t ray_runs);
  // A per-tile frame: classifies its tiles on the GPU (after begin_frame()).
  void classify(const TileClassifyInputs& inputs);
  // The ray list's budget for the frame begin_frame() just decided.
  std::uint32_t max_rays() const { return max_rays_; }
  TileClassifyPass& pass() { return pass_; }
  const TileClassifyPass& pass() const { return pass_; }

  // The path of the frame in readback slot `slot`, and its ray-traced run (nullopt: all SSR, no rays).
  ReflectionPath path(std::size_t slot) const { return decisions_[slot].path; }
  std::optional<std::uint64_t> ray_run(std::size_t slot) const { return decisions_[slot].ray_run; }
  // The last frame's tile classes for the debug views: the classification's on a per-tile frame; on
  // a whole-frame path the path's class on every tile with a reflective pixel (of the G-buffer's
  // albedo_reflectivity and world_position, top row first, as read back).
  std::vector<TileClass> last_classes(const ImageRgbaF& albedo_reflectivity, const ImageRgbaF& world_position) const;

  // After the frame's GPU work was issued: queue its readback.
  void finish_frame(std::size_t slot);
  // The frame of readback slot `slot`, once the GPU is past it, with what its SSR counted (nullopt:
  // SSR did not run) and the reflective pixels its ray list saw (nullopt: no rays).
  std::optional<AdaptiveFrameStats> take_stats(std::size_t slot, bool wait, const std::optional<SsrCounts>& ssr,
                                               std::optional<std::uint32_t> traced_reflective);
  // One finished frame's timers and counts: the cost model learns from them.
  void observe(const CostSample& sample);
  const ReflectionCostModel& cost_model() const { return costs_; }

private:
  ReflectionPath choose_path();
  void read_newest_tiles();

  AdaptiveSettings settings_;
  float scene_diagonal_;
  TileClassifyPass pass_;
  ReflectionCostModel costs_;
  BudgetGovernor governor_;
  std::optional<CameraState> previous_camera_;
  std::uint64_t frames_ = 0;
  std::uint64_t observed_ = 0;  // frames whose timers came back
  std::optional<std::uint64_t> newest_read_;  // the frame whose tiles the host last used
  std::vector<TileEvidence> newest_tiles_;
  std::uint32_t max_rays_ = 0;
  // The path of the frames since path_since_; per-tile frames may leave it once the tiles of frame
  // first_deciding_frame_ (the first with history after the last reset) are read.
  ReflectionPath path_ = ReflectionPath::per_tile;
  std::uint64_t path_since_ = 0;
  std::uint64_t first_deciding_frame_ = 1;
  // The newest frame whose counts came back: its reflective pixels, and whether SSR alone (a whole
  // frame of it) stayed within the quality target.
  std::optional<std::uint64_t> newest_counted_;
  double newest_reflective_ = 0.0;
  bool ssr_alone_within_target_ = true;
  // Per slot: the host's side of the frame's decision.
  struct Decision {
    ReflectionPath path = ReflectionPath::per_tile;
    std::optional<std::uint64_t> ray_run;
    std::optional<double> ray_budget;
    float budget_factor = 1.0f;
    TileThresholds thresholds;
    ReflectionStageCosts costs;
    std::optional<TileClass> forced;  // the calibration frames: every reflective tile's class
  };
  std::array<Decision, kFramesInFlight> decisions_{};
  std::array<std::uint64_t, kFramesInFlight> slot_frame_{};
  std::size_t slot_ = 0;  // the slot of the frame begin_frame() decided last
};

}  // namespace glint::render
