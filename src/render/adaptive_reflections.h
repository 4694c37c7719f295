#pragma once
// AdaptiveReflections: the host half of `--reflections auto` (docs/hybrid.md "auto"). Per frame,
// before SSR: the budget for this frame (ReflectionBudget scaled by the camera's motion), the
// thresholds of the tile rule from the newest tiles the host has read back and the cost model
// (tile_classification.h, reflection_cost_model.h), then TileClassifyPass on the GPU, which hands
// SSR and the ray list their tile lists. After the frame its timers feed the cost model
// (observe(), called by app/frame_loop.cpp when the frame's measurements come back).
#include "gl/gpu_timer.h"
#include "render/reflection_budget.h"
#include "render/reflection_cost_model.h"
#include "render/tile_classify_pass.h"

#include <array>
#include <cstdint>
#include <optional>

namespace glint::render {

struct AdaptiveSettings {
  ReflectionBudget budget;
  // The quality target (ThresholdInputs::max_unreflected_fraction).
  float max_unreflected_fraction = 0.0f;
  // Costs that never change instead of the measured ones (tests; decisions free of timing noise).
  std::optional<ReflectionCosts> fixed_costs;

  void validate() const;  // glint::Error naming the bad field
};

// What auto decided for one frame (timings.csv's adaptive columns).
struct AdaptiveFrameStats {
  std::array<std::uint32_t, kTileClassCount> class_tiles{};   // per TileClass
  std::array<std::uint32_t, kTileClassCount> class_pixels{};  // reflective pixels per class
  std::uint32_t reflective_pixels = 0;                        // all classes
  std::uint32_t rays_wanted = 0;                              // before the budget cut
  std::optional<double> ray_budget;                           // this frame's, after motion
  float budget_factor = 1.0f;                                 // motion's share of the budget
  TileThresholds thresholds;
  ReflectionCosts costs;  // the cost model's estimate the thresholds came from
};

class AdaptiveReflections {
public:
  // `device_tracing`: the backend traces on the GPU (its prior costs); `scene_diagonal` scales the
  // camera's travel (camera_motion).
  AdaptiveReflections(int width, int height, const AdaptiveSettings& settings, bool device_tracing,
                      float scene_diagonal);

  // Decides and classifies frame `slot`'s tiles (slot = frame % kFramesInFlight).
  void classify(const TileClassifyInputs& inputs, const CameraState& camera, std::size_t slot);
  // The ray list's tiles and budget for the frame classify() just decided.
  std::uint32_t max_rays() const { return max_rays_; }
  TileClassifyPass& pass() { return pass_; }
  const TileClassifyPass& pass() const { return pass_; }

  // After the frame's GPU work was issued: queue its readback.
  void finish_frame(std::size_t slot);
  // The frame of readback slot `slot`, once the GPU is past it.
  std::optional<AdaptiveFrameStats> take_stats(std::size_t slot, bool wait);
  // One finished frame's timers and counts: the cost model learns from them.
  void observe(const CostSample& sample) { costs_.observe(sample); }
  const ReflectionCostModel& cost_model() const { return costs_; }

private:
  AdaptiveSettings settings_;
  float scene_diagonal_;
  TileClassifyPass pass_;
  ReflectionCostModel costs_;
  BudgetGovernor governor_;
  std::optional<CameraState> previous_camera_;
  std::uint64_t frames_ = 0;
  std::optional<std::uint64_t> newest_read_;  // the frame whose tiles the host last used
  std::vector<TileEvidence> newest_tiles_;
  std::uint32_t max_rays_ = 0;
  // Per slot: the host's side of the frame's decision.
  struct Decision {
    std::optional<double> ray_budget;
    float budget_factor = 1.0f;
    TileThresholds thresholds;
    ReflectionCosts costs;
  };
  std::array<Decision, kFramesInFlight> decisions_{};
  std::array<std::uint64_t, kFramesInFlight> slot_frame_{};
};

}  // namespace glint::render
