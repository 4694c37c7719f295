#include "render/reflection_budget.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>

namespace glint::render {

void ReflectionBudget::validate() const {
  if (ms && !(*ms > 0.0 && std::isfinite(*ms))) fail("reflection budget: {} ms must be finite and > 0", *ms);
  if (!(fast_motion_factor > 0.0f && fast_motion_factor <= 1.0f))
    fail("reflection budget: the fast-motion factor {} must be in (0, 1]", fast_motion_factor);
  if (!(still_motion >= 0.0f && fast_motion > still_motion))
    fail("reflection budget: still motion {} must be >= 0 and below fast motion {}", still_motion, fast_motion);
  if (!(recovery_per_frame > 0.0f && recovery_per_frame <= 1.0f))
    fail("reflection budget: the recovery per frame {} must be in (0, 1]", recovery_per_frame);
}

float camera_motion(const CameraState& previous, const CameraState& current, float scene_diagonal) {
  const vec3 a = previous.target - previous.position, b = current.target - current.position;
  float turn = 0.0f;
  if (length(a) > 0.0f && length(b) > 0.0f)
    turn = std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0f, 1.0f));
  const float fov = std::max(1e-3f, current.fov_y_degrees * 3.14159265f / 180.0f);
  const float travel = length(current.position - previous.position);
  const float travel_scale = std::max(1e-6f, 0.1f * scene_diagonal);
  return turn / fov + travel / travel_scale;
}

float motion_budget_factor(const ReflectionBudget& budget, float motion) {
  if (!(motion > budget.still_motion)) return 1.0f;
  const float x = std::clamp((motion - budget.still_motion) / (budget.fast_motion - budget.still_motion), 0.0f, 1.0f);
  const float smooth = x * x * (3.0f - 2.0f * x);
  return 1.0f - (1.0f - budget.fast_motion_factor) * smooth;
}

float BudgetGovernor::next(float motion) {
  const float allowed = motion_budget_factor(budget_, motion);
  factor_ = allowed < factor_ ? allowed : std::min(allowed, factor_ + budget_.recovery_per_frame);
  return factor_;
}

}  // namespace glint::render
