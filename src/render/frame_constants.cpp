#include "render/frame_constants.h"

#include "core/error.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace glint::render {

vec2 clip_range_for(const Aabb& world_bounds) {
  // Relative to the scene's size: floors in world units (far >= 1, near >= 0.01) once clipped a scene
  // a thousandth of the atrium's size away entirely. Near is 1 cm where that is 1/10000 to 1/8000 of
  // far, as before for a scene the atrium's size (whose frames stay bit-identical), else the nearer
  // end of that range.
  const float diagonal = world_bounds.empty() ? 0.0f : glm::length(world_bounds.extent());
  const float far_plane = std::isfinite(diagonal) && diagonal > 0.0f ? 2.0f * diagonal : 200.0f;
  return {std::clamp(0.01f, far_plane * 1e-4f, far_plane * 1.25e-4f), far_plane};
}

FrameConstants make_frame_constants(const Scene& scene, const Aabb& world_bounds, const FrameState& frame, int width,
                                    int height) {
  if (width <= 0 || height <= 0) fail("frame constants: invalid viewport {}x{}", width, height);
  const vec2 clip = clip_range_for(world_bounds);
  FrameConstants constants;
  constants.view = frame.camera.view();
  constants.projection = glm::perspective(glm::radians(frame.camera.fov_y_degrees),
                                          static_cast<float>(width) / static_cast<float>(height), clip.x, clip.y);
  constants.view_projection = constants.projection * constants.view;
  constants.inverse_view = glm::inverse(constants.view);
  constants.inverse_projection = glm::inverse(constants.projection);
  constants.camera_position = vec4(frame.camera.position, 1.0f);
  constants.light_position_range = vec4(frame.light_position, scene.light.range);
  constants.light_color_intensity = vec4(scene.light.color, scene.light.intensity);
  constants.sky_color = vec4(scene.sky_color, 1.0f);
  constants.near_far = vec4(clip.x, clip.y, 0.0f, 0.0f);
  constants.viewport = glm::ivec4(width, height, frame.frame, 0);
  constants.relative_view_projection = constants.projection * mat4(glm::mat3(constants.view));
  return constants;
}

}  // namespace glint::render
