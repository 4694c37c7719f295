#version 450 core
// Shadow rays traced where they are made (RayTracedShadows with the gl backend, docs/render.md
// "Shadow methods"): one invocation per pixel makes the pixel's shadow ray (include/pixel_shadow_ray.glsl),
// walks the gl backend's structures with it (include/gl_rt_traverse.glsl's occlusion query, bound by
// rt::GlTracing::bind_inline_tracing) and writes the mask (include/shadow_ray_mask_rule.glsl): the
// same rays, walk and mask as the three steps shadow_rays.comp.glsl, trace_any_gl and
// shadow_ray_mask.comp.glsl, in one dispatch and without the ray list (32 bytes a pixel written and
// read back) or the answers between them.
// One work group is one 8 x 4 block of pixels (kShadowRayBlock, include/shadow_ray_index.glsl): a
// warp's 32 rays start close together and walk much the same nodes, as the blocks of the dense list
// give the trace kernel's groups of 32.
#include "include/frame_constants.glsl"
#include "include/gl_rt_traverse.glsl"
#include "include/pixel_shadow_ray.glsl"
#include "include/shadow_ray_index.glsl"

layout(local_size_x = kShadowRayBlock.x, local_size_y = kShadowRayBlock.y) in;

// The mask written: not cube_shadow_mask (hybrid: a copy of the cube's mask, which neighbours read).
layout(binding = 4, r8) uniform writeonly image2D shadow_mask;

void main() {
  const ivec2 size = imageSize(world_position);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, size))) return;
  const Ray ray = pixel_shadow_ray(pixel, size);
  float value;
  if (shadow_ray_mask_value(ray, !is_empty(ray) && trace_occluded(ray.origin, ray.direction, ray.t_min, ray.t_max),
                            value))
    imageStore(shadow_mask, pixel, vec4(value));
}
