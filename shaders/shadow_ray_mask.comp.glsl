#version 450 core
// Shadow mask from shadow rays (RayTracedShadows): at every pixel that cast a ray (t_min <= t_max),
// 0 when the ray tracer found an occluder, else 1. Pixels without a ray (t_max = 0 < t_min) get what
// shadow_rays.comp.glsl decided by t_min: 1 keep the cube map's value (hybrid), 2 unlit (0),
// 3 background (1).
layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 3, r8) uniform writeonly image2D shadow_mask;

struct Ray { vec3 origin; float t_min; vec3 direction; float t_max; };  // accel::Ray
layout(std430, binding = 10) readonly buffer ShadowRays { Ray rays[]; };
#include "include/occlusion_flag.glsl"
#include "include/shadow_ray_index.glsl"

void main() {
  const ivec2 size = imageSize(shadow_mask);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const uint i = uint(shadow_ray_index(pixel, size));
  const float t_min = rays[i].t_min;
  if (t_min > rays[i].t_max) {
    if (t_min == 2.0) imageStore(shadow_mask, pixel, vec4(0.0));
    else if (t_min == 3.0) imageStore(shadow_mask, pixel, vec4(1.0));
    return;
  }
  imageStore(shadow_mask, pixel, vec4(occluded(i) ? 0.0 : 1.0));
}
