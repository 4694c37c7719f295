#version 450 core
// Ray list (RayListPass, docs/hybrid.md): compacts the pixels that need a ray-traced reflection into
// a list of mirror rays. A pixel is listed when it is reflective (geometry with reflectivity > 0) and
// either trace_all is set (rt mode: every reflective pixel) or SSR marked it failed (hybrid mode).
//   origin    = G-buffer world position + origin_offset * n
//   direction = reflect(-v, n), unit length, t in [0, inf); on a glossy surface a GGX sample around
//               it (pixel_reflection_direction, include/glossy_sampling.glsl, docs/glossy.md)
// where v is the unit direction to the camera and n the G-buffer normal turned towards the camera.
// Slots are handed out per work group (one global atomicAdd per group), so the list order varies
// from run to run but every listed pixel appears exactly once.
// --reflections auto (use_tile_list): one work group per tile of the ray tile list
// (include/tile_list.glsl); a rays-only tile lists every reflective pixel, an SSR + rays tile its
// SSR-failed ones. Slots at or past max_rays (the frame's ray budget) are not written;
// ray_budget_clamp.comp.glsl then cuts the count to max_rays, so a budget is never exceeded.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/tile_class_rule.glsl"
#include "include/tile_list.glsl"
#include "include/glossy_sampling.glsl"

layout(binding = 0, rgba8) uniform readonly image2D albedo_reflectivity;
layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, rgba16f) uniform readonly image2D world_normal;
layout(binding = 3, r8ui) uniform readonly uimage2D failure_mask;

struct Ray { vec3 origin; float t_min; vec3 direction; float t_max; };  // accel::Ray
layout(std430, binding = 6) writeonly buffer Rays { Ray rays[]; };
layout(std430, binding = 7) writeonly buffer RayPixels { uint ray_pixels[]; };
layout(std430, binding = 9) buffer RayCounters { uint ray_count; uint reflective_count; };

uniform int trace_all;
uniform float origin_offset;
uniform int max_rays;  // >= 0

shared uint group_rays;
shared uint group_reflective;
shared uint group_base;

void main() {
  if (gl_LocalInvocationIndex == 0u) { group_rays = 0u; group_reflective = 0u; }
  barrier();

  const ivec2 size = imageSize(world_position);
  const ivec2 pixel = tile_list_pixel();
  const bool trace_tile = trace_all != 0 || tile_list_class() == kTileRtOnly;
  bool listed = false;
  uint slot = 0u;
  if (all(lessThan(pixel, size))) {
    const bool reflective = imageLoad(world_position, pixel).w != 0.0 && imageLoad(albedo_reflectivity, pixel).a > 0.0;
    if (reflective) atomicAdd(group_reflective, 1u);
    listed = reflective && (trace_tile || imageLoad(failure_mask, pixel).r == 1u);
    if (listed) slot = atomicAdd(group_rays, 1u);
  }
  barrier();
  // Only groups with something to add touch the two global counters: every group's atomics go to the
  // same two words, so the groups without reflective pixels should not queue behind the others.
  if (gl_LocalInvocationIndex == 0u) {
    group_base = group_rays != 0u ? atomicAdd(ray_count, group_rays) : 0u;
    if (group_reflective != 0u) atomicAdd(reflective_count, group_reflective);
  }
  barrier();
  if (!listed || group_base + slot >= uint(max_rays)) return;

  const vec3 position = imageLoad(world_position, pixel).xyz;
  const vec4 normal_roughness = imageLoad(world_normal, pixel);
  vec3 n = normalize(normal_roughness.xyz);
  const vec3 v = normalize(camera_position.xyz - position);
  if (dot(n, v) < 0.0) n = -n;
  const uint i = group_base + slot;
  // The mirror direction, or a GGX sample of it on a glossy surface (include/glossy_sampling.glsl).
  const vec3 direction = pixel_reflection_direction(-v, n, normal_roughness.w, pixel);
  rays[i] = Ray(position + origin_offset * n, 0.0, direction, uintBitsToFloat(0x7f800000u));
  ray_pixels[i] = uint(pixel.y * size.x + pixel.x);
}
