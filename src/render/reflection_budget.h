#pragma once
// The reflection budget of `--reflections auto` (docs/hybrid.md "auto"): `--ray-budget N` rays or
// `--reflection-budget MS` milliseconds per frame, scaled by the camera's motion as the paper's
// future work suggests: while the camera moves fast the eye cannot follow detail, so the budget
// drops (fewer rays, more SSR); once the camera is still again it climbs back over a few frames.
#include "scene/camera_path.h"

#include <cstdint>
#include <optional>

namespace glint::render {

struct ReflectionBudget {
  std::optional<std::uint32_t> rays;  // --ray-budget
  std::optional<double> ms;           // --reflection-budget (converted to rays by the cost model)
  // The budget's share left at full speed (1: motion changes nothing).
  float fast_motion_factor = 0.25f;
  // Camera motion per frame (camera_motion's unit) below which the camera counts as still, and from
  // which on as fast.
  float still_motion = 0.01f;
  float fast_motion = 0.1f;
  // How much of the full budget comes back per still frame.
  float recovery_per_frame = 0.1f;

  bool limited() const { return rays.has_value() || ms.has_value(); }
  void validate() const;  // glint::Error naming the bad field
};

// How far the image moved between two frames, as a fraction of the screen: the view direction's
// turn over the vertical field of view plus the camera's travel over a tenth of the scene's
// diagonal (about the distance of what fills an interior view, whose image shifts by the travel
// over that distance). The walkthroughs' walking pace is about 0.01 per frame.
float camera_motion(const CameraState& previous, const CameraState& current, float scene_diagonal);

// The factor motion leaves of the budget, frame after frame: it drops at once to the share the
// motion allows and climbs back by recovery_per_frame per frame while the camera is slower.
class BudgetGovernor {
public:
  explicit BudgetGovernor(const ReflectionBudget& budget) : budget_(budget) {}
  // The factor for a frame whose camera moved by `motion` since the last one.
  float next(float motion);
  float factor() const { return factor_; }

private:
  ReflectionBudget budget_;
  float factor_ = 1.0f;
};

// The share of the budget a motion allows: 1 up to still_motion, fast_motion_factor from fast_motion
// on, smooth in between.
float motion_budget_factor(const ReflectionBudget& budget, float motion);

}  // namespace glint::render
