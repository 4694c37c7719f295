#version 450 core
// Shadow mask from shadow rays (RayTracedShadows): each pixel's value from its ray and the ray
// tracer's answer by include/shadow_ray_mask_rule.glsl (0 occluded, 1 not; a ray-less pixel by its
// empty ray: unlit 0, background 1, hybrid keeps the cube map's value).
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 3, r8) uniform writeonly image2D shadow_mask;

#include "include/shadow_ray_mask_rule.glsl"
layout(std430, binding = 10) readonly buffer ShadowRays { Ray rays[]; };
#include "include/occlusion_flag.glsl"
#include "include/shadow_ray_index.glsl"

void main() {
  const ivec2 size = imageSize(shadow_mask);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const uint i = uint(shadow_ray_index(pixel, size));
  const Ray ray = rays[i];
  float value;
  if (shadow_ray_mask_value(ray, !is_empty(ray) && occluded(i), value)) imageStore(shadow_mask, pixel, vec4(value));
}
