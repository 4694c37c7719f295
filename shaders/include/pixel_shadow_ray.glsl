// A pixel's shadow ray (RayTracedShadows, docs/render.md "Shadow methods"), the one rule of both
// ways it is traced: shadow_rays.comp.glsl writes it into the dense ray list (cpu, embree, cuda,
// optix, and the gl backend's three-step path), shadow_rays_inline.comp.glsl traces it where it is
// made (gl backend). For a lit G-buffer pixel:
//   origin    = world position + origin_offset * n   (n: the G-buffer normal turned towards the camera)
//   direction = light position - origin (unnormalised), t in [0, kShadowRayEnd]: the light is at t = 1
// Pixels that need no ray get an empty ray whose t_min says their value (shadow_ray_mask_rule.glsl):
//   background                                    -> kShadowRayBackground (1, as the cube's mask)
//   facing away from the light (N.L <= 0, N turned
//   towards the camera as the lighting pass does)  -> kShadowRayUnlit (0, unlit whatever the shadow says)
//   hybrid: the cube's filtered value is certain   -> kShadowRayKeep (kept: fully lit or fully shadowed,
//           (0 or 1, as are its 4 neighbours',        as are its neighbours, no depth edge)
//           and no depth edge)
// The includer also includes frame_constants.glsl and binds the images below. cube_shadow_mask is only
// read, so neighbours see the cube's values whatever the order of invocations: a pass that writes the
// mask reads a copy of it here.
#include "include/shadow_ray_mask_rule.glsl"

layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, rgba16f) uniform readonly image2D world_normal;
// hybrid: the cube map's mask (rt: not read)
layout(binding = 3, r8) uniform readonly image2D cube_shadow_mask;

uniform float origin_offset;
uniform int hybrid;  // 1: rays only where the cube's mask is uncertain
uniform float depth_edge_fraction;

// The light sits at t = 1; an occluder must be strictly before it (the tracers' interval is inclusive).
const float kShadowRayEnd = 1.0 - 1e-4;

bool cube_value_uncertain(ivec2 pixel, ivec2 size, float value, float camera_distance) {
  if (value > 0.0 && value < 1.0) return true;  // partly lit: a PCF edge
  const ivec2 offsets[4] = ivec2[](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
  for (int k = 0; k < 4; ++k) {
    const ivec2 q = clamp(pixel + offsets[k], ivec2(0), size - 1);
    if (imageLoad(cube_shadow_mask, q).r != value) return true;  // a shadow edge runs between the pixels
    const vec4 p = imageLoad(world_position, q);
    if (p.w == 0.0 || abs(distance(p.xyz, camera_position.xyz) - camera_distance) > depth_edge_fraction * camera_distance)
      return true;  // a depth edge: contact shadows and thin occluders a small cube map misses
  }
  return false;
}

// The shadow ray of `pixel` (inside the size x size G-buffer).
Ray pixel_shadow_ray(ivec2 pixel, ivec2 size) {
  const vec4 position = imageLoad(world_position, pixel);
  if (position.w == 0.0) return empty_pixel_shadow_ray(kShadowRayBackground);
  vec3 n = normalize(imageLoad(world_normal, pixel).xyz);
  const vec3 to_light = light_position_range.xyz - position.xyz;
  if (dot(n, camera_position.xyz - position.xyz) < 0.0) n = -n;  // the side the lighting pass shades
  if (dot(n, to_light) <= 0.0) return empty_pixel_shadow_ray(kShadowRayUnlit);
  if (hybrid != 0) {
    const float value = imageLoad(cube_shadow_mask, pixel).r;
    if (!cube_value_uncertain(pixel, size, value, distance(position.xyz, camera_position.xyz)))
      return empty_pixel_shadow_ray(kShadowRayKeep);
  }
  // `precise` (no fused multiply-add, no reordering, back through every operation the ray depends on):
  // a pass that traces the ray inline feeds it to the walk's precise box and triangle tests, which
  // would forbid contracting its arithmetic there while shadow_rays.comp.glsl may contract it; so
  // both make the ray by the stated operations and trace the same ray.
  precise vec3 origin = position.xyz + origin_offset * n;
  precise vec3 direction = light_position_range.xyz - origin;
  return Ray(origin, 0.0, direction, kShadowRayEnd);
}
