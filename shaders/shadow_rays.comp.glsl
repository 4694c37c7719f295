#version 450 core
// Shadow rays (RayTracedShadows, docs/render.md "Shadow methods"): one ray per pixel, dense (in
// blocks of 8 x 4 pixels: include/shadow_ray_index.glsl), so nothing is counted and no count is read
// back. For a lit G-buffer pixel:
//   origin    = world position + origin_offset * n   (n: the G-buffer normal turned towards the light)
//   direction = light position - origin (unnormalised), t in [0, kShadowRayEnd]: the light is at t = 1
// Pixels that need no ray get an empty ray (t_max = 0 < t_min, which every backend's any-hit
// rejects at once) whose t_min tells the mask pass (shadow_ray_mask.comp.glsl) their value:
//   background                                    t_min 3 -> 1 (as the cube's mask)
//   facing away from the light (N.L <= 0, N turned
//   towards the camera as the lighting pass does)  t_min 2 -> 0 (unlit whatever the shadow says)
//   hybrid: the cube's filtered value is certain   t_min 1 -> kept (fully lit or fully shadowed, as
//           (0 or 1, as are its 4 neighbours',              are its neighbours, no depth edge)
//           and no depth edge)
// This pass only reads the mask, so neighbours see the cube's values whatever the order of invocations.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/shadow_ray_index.glsl"

layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, rgba16f) uniform readonly image2D world_normal;
// hybrid: the cube map's mask (rt: not read)
layout(binding = 3, r8) uniform readonly image2D shadow_mask;

struct Ray { vec3 origin; float t_min; vec3 direction; float t_max; };  // accel::Ray
layout(std430, binding = 10) writeonly buffer ShadowRays { Ray rays[]; };

uniform float origin_offset;
uniform int hybrid;              // 1: rays only where the cube's mask is uncertain
uniform float depth_edge_fraction;

// The light sits at t = 1; an occluder must be strictly before it (the tracers' interval is inclusive).
const float kShadowRayEnd = 1.0 - 1e-4;
// t_min of the empty rays (t_max = 0), read by the mask pass.
const float kKeep = 1.0, kUnlit = 2.0, kBackground = 3.0;

bool uncertain(ivec2 pixel, ivec2 size, float value, float camera_distance) {
  if (value > 0.0 && value < 1.0) return true;  // partly lit: a PCF edge
  const ivec2 offsets[4] = ivec2[](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  for (int k = 0; k < 4; ++k) {
    const ivec2 q = clamp(pixel + offsets[k], ivec2(0), size - 1);
    if (imageLoad(shadow_mask, q).r != value) return true;  // a shadow edge runs between the pixels
    const vec4 p = imageLoad(world_position, q);
    if (p.w == 0.0 || abs(distance(p.xyz, camera_position.xyz) - camera_distance) > depth_edge_fraction * camera_distance)
      return true;  // a depth edge: contact shadows and thin occluders a small cube map misses
  }
  return false;
}

void main() {
  const ivec2 size = imageSize(world_position);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const uint i = uint(shadow_ray_index(pixel, size));
  const vec4 position = imageLoad(world_position, pixel);
  if (position.w == 0.0) {
    rays[i] = Ray(vec3(0.0), kBackground, vec3(0.0, 0.0, 1.0), 0.0);
    return;
  }
  vec3 n = normalize(imageLoad(world_normal, pixel).xyz);
  const vec3 to_light = light_position_range.xyz - position.xyz;
  if (dot(n, camera_position.xyz - position.xyz) < 0.0) n = -n;  // the side the lighting pass shades
  if (dot(n, to_light) <= 0.0) {
    rays[i] = Ray(vec3(0.0), kUnlit, vec3(0.0, 0.0, 1.0), 0.0);
    return;
  }
  if (hybrid != 0) {
    const float value = imageLoad(shadow_mask, pixel).r;
    if (!uncertain(pixel, size, value, distance(position.xyz, camera_position.xyz))) {
      rays[i] = Ray(vec3(0.0), kKeep, vec3(0.0, 0.0, 1.0), 0.0);
      return;
    }
  }
  const vec3 origin = position.xyz + origin_offset * n;
  rays[i] = Ray(origin, 0.0, light_position_range.xyz - origin, kShadowRayEnd);
}
