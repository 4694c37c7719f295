#include "scene/default_walkthrough.h"

#include <glm/gtc/constants.hpp>

namespace glint {

void assign_default_walkthrough(Scene& scene) {
  const Aabb bounds = scene.world_bounds();
  if (bounds.empty()) return;
  const vec3 center = bounds.center();
  const vec3 extent = bounds.extent();
  const float eye_height = bounds.min.y + extent.y / 3.0f;

  // Eight points on an ellipse at 40 % of the half-extents, closed by repeating the first.
  CameraPathSpec camera;
  constexpr int kPoints = 8;
  for (int i = 0; i <= kPoints; ++i) {
    const float angle = glm::two_pi<float>() * static_cast<float>(i) / kPoints;
    camera.points.push_back(vec3(center.x + 0.4f * extent.x * std::cos(angle), eye_height,
                                 center.z + 0.4f * extent.z * std::sin(angle)));
    camera.targets.push_back(vec3(center.x, eye_height, center.z));
  }
  scene.walkthrough.camera = camera;

  const bool along_x = extent.x >= extent.z;
  const float light_height = bounds.min.y + 0.8f * extent.y;
  const vec3 half_sweep = along_x ? vec3(0.35f * extent.x, 0.0f, 0.0f) : vec3(0.0f, 0.0f, 0.35f * extent.z);
  const vec3 light_center(center.x, light_height, center.z);
  scene.walkthrough.light.points = {light_center - half_sweep, light_center + half_sweep};
  scene.light.position = light_center;
  scene.light.range = std::max(glm::length(extent), 1e-3f);
}

}  // namespace glint
