#version 450 core
// Shadow rays (RayTracedShadows, docs/render.md "Shadow methods"): one ray per pixel by the rule of
// include/pixel_shadow_ray.glsl, dense (in blocks of 8 x 4 pixels: include/shadow_ray_index.glsl), so
// nothing is counted and no count is read back; a ray tracer answers them and
// shadow_ray_mask.comp.glsl makes the mask. The gl backend makes, traces and masks them in one pass
// instead (shadow_rays_inline.comp.glsl) unless asked for these three steps.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/pixel_shadow_ray.glsl"
#include "include/shadow_ray_index.glsl"

layout(std430, binding = 10) writeonly buffer ShadowRays { Ray rays[]; };

void main() {
  const ivec2 size = imageSize(world_position);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  rays[uint(shadow_ray_index(pixel, size))] = pixel_shadow_ray(pixel, size);
}
