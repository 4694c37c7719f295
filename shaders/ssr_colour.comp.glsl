#version 450 core
// SSR's colour fetch (SsrPass::shade, docs/ssr.md "March, then colour"): for each pixel whose march
// (ssr.comp.glsl) found a trusted hit, the lit colour where the ray met the hit's surface, weighted by
// the reflection's BRDF weight, into the reflection image's rgb (its a, the hit distance, is the
// march's). Pixels without a trusted hit keep the march's zeros. It runs after lighting, the march
// before it.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/ssr_hit.glsl"
#include "include/tile_list.glsl"  // --reflections auto: the march's tiles (render/tile_dispatch.h)

layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, rgba16f) uniform readonly image2D world_normal;
layout(binding = 3, rgba16f) uniform readonly image2D lit;
layout(binding = 4, rgba16f) uniform image2D reflection;
layout(binding = 6, rgba32ui) uniform readonly uimage2D ssr_hits;

ivec2 screen_size;

#include "include/ssr_lit_at.glsl"  // lit_at: needs world_position, lit and screen_size above

void main() {
  screen_size = imageSize(world_position);
  const ivec2 pixel = tile_list_pixel();
  if (any(greaterThanEqual(pixel, screen_size))) return;
  SsrHit hit;
  if (!unpack_ssr_hit(imageLoad(ssr_hits, pixel), hit)) return;
  const vec3 hit_position = imageLoad(world_position, hit.pixel).xyz;
  const vec3 hit_normal = normalize(imageLoad(world_normal, hit.pixel).xyz);
  const float footprint = pixel_footprint(-view_from_world(hit_position).z, screen_size.y);
  const float hit_distance = imageLoad(reflection, pixel).a;
  imageStore(reflection, pixel, vec4(hit.weight * lit_at(hit.point, hit.pixel, hit_position, hit_normal, footprint),
                                     hit_distance));
}
