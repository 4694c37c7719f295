// Where a world point was on the previous frame's screen (ReflectionDenoiser, docs/glossy.md):
// the camera's motion vector of a pixel, from the previous frame's view-projection. In pixels, x
// right, y up, pixel centres at +0.5; w <= 0 (behind the previous camera) gives (-1, -1).
#include "include/denoiser_guide.glsl"

vec2 previous_pixel_position(mat4 previous_view_projection, vec3 world, vec2 size) {
  const vec4 clip = previous_view_projection * vec4(world, 1.0);
  if (clip.w <= 0.0) return vec2(-1.0);
  return (clip.xy / clip.w * 0.5 + 0.5) * size;
}

// Whether a previous-frame surface sample (include/denoiser_guide.glsl's guide of pixel `tap` of
// the previous frame, whose rays are `rays`) is the same surface as the current one: reflective, on
// its plane within depth_tolerance x the distance to the camera, and facing the same way.
bool same_surface(vec3 position, vec3 normal, float camera_distance, GuideRays rays, ivec2 tap, uvec2 previous_guide,
                  float depth_tolerance) {
  if (!guide_reflective(previous_guide)) return false;
  return abs(dot(normal, guide_position(rays, tap, previous_guide) - position)) <= depth_tolerance * camera_distance &&
         dot(normal, guide_normal(previous_guide)) > 0.9;
}
