#pragma once
// Per-frame values every pass reads: camera, projection, light, sky, viewport. One std140 uniform
// block at binding kFrameConstantsBinding, declared identically in every shader that needs it:
//
//   layout(std140, binding = 0) uniform FrameConstants {
//     mat4 view; mat4 projection; mat4 view_projection; mat4 inverse_view; mat4 inverse_projection;
//     vec4 camera_position;        // xyz world, w unused
//     vec4 light_position_range;   // xyz world, w = PointLight::range
//     vec4 light_color_intensity;  // rgb linear colour, w = intensity
//     vec4 sky_color;              // rgb linear, w unused
//     vec4 near_far;               // x near, y far (world units), zw unused
//     ivec4 viewport;              // x width, y height, z frame number, w unused
//     vec4 reflection_sampling;    // x SSR roughness cutoff, y sample index, z samples per pixel,
//                                  // w 1 = glossy reflections (0: every surface a mirror); docs/glossy.md
//     mat4 relative_view_projection;  // projection * view without its translation: takes positions
//                                     // relative to camera_position (camera-relative rendering)
//   };
#include "core/math.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <cstdint>
#include <type_traits>

namespace glint::render {

// Uniform-buffer binding points (apart from the storage bindings' numbers): 0 this block, the only
// uniform block glint binds. GlSceneDeformer's pass has none: each mesh's deformation is a DeformJob
// in a storage buffer (binding 18) and the frame's time a plain uniform (sine_deform.comp.glsl).
inline constexpr unsigned kFrameConstantsBinding = 0;

struct FrameConstants {
  mat4 view{1.0f};
  mat4 projection{1.0f};
  mat4 view_projection{1.0f};
  mat4 inverse_view{1.0f};
  mat4 inverse_projection{1.0f};
  vec4 camera_position{0.0f};
  vec4 light_position_range{0.0f};
  vec4 light_color_intensity{0.0f};
  vec4 sky_color{0.0f};
  vec4 near_far{0.0f};
  glm::ivec4 viewport{0};
  vec4 reflection_sampling{0.0f};  // all 0: mirrors (render/reflection_sampling.h writes it)
  // Clip space from a position relative to camera_position: the passes that project world points
  // subtract the camera first (include/frame_constants.glsl clip_from_world), so far from the origin
  // the rounding of large coordinates stays a common perturbation of the point instead of entering
  // clip z and w separately (docs/render.md "precision far from the origin").
  mat4 relative_view_projection{1.0f};
};
static_assert(std::is_standard_layout_v<FrameConstants> && sizeof(FrameConstants) == 6 * 64 + 7 * 16,
              "FrameConstants must match the std140 block above");

// Near and far clip distances that enclose `world_bounds` from any camera inside or near it: far is
// twice the box diagonal, near 1/10000 to 1/8000 of far (1 cm where that is in the range), so a scene
// of any scale gets about the same depth precision (an empty or infinite box: as for a diagonal of 100).
vec2 clip_range_for(const Aabb& world_bounds);

// The constants of one frame: the camera's view and an OpenGL perspective projection (depth -1..1,
// aspect width / height, the camera's vertical field of view, clip range from `world_bounds`, the
// scene's bounds this frame), the light at the frame's position.
FrameConstants make_frame_constants(const Scene& scene, const Aabb& world_bounds, const FrameState& frame, int width,
                                    int height);

}  // namespace glint::render
