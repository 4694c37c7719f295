#version 450 core
// SSR's colour fetch (SsrPass::shade, docs/ssr.md "March, then colour"): for each pixel whose march
// (ssr.comp.glsl) found a trusted hit, the lit colour where the ray met the hit's surface, seen from
// the reflecting surface (seen_along_ray, include/ssr_lit_at.glsl), weighted by
// the reflection's BRDF weight, into the reflection image's rgb (its a, the hit distance, is the
// march's). Pixels without a trusted hit keep the march's zeros. It runs after lighting, the march
// before it.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/glossy_sampling.glsl"  // the reflected ray's direction, as the march traced it
#include "include/ssr_hit.glsl"
#include "include/tile_list.glsl"  // --reflections auto: the march's tiles (render/tile_dispatch.h)

layout(binding = 0, rgba8) uniform readonly image2D albedo_reflectivity;
layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, rgba16f) uniform readonly image2D world_normal;
layout(binding = 3, rgba16f) uniform readonly image2D lit;
layout(binding = 4, rgba16f) uniform image2D reflection;
layout(binding = 6, rgba32ui) uniform readonly uimage2D ssr_hits;

ivec2 screen_size;

#include "include/ssr_lit_at.glsl"  // lit_at, seen_along_ray: need the images and screen_size above

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
  // The ray's direction as the march computed it (include/ssr_march.glsl), for the view of the hit.
  const vec3 origin = imageLoad(world_position, pixel).xyz;
  const vec4 normal_roughness = imageLoad(world_normal, pixel);
  const vec3 ray = pixel_reflection_direction(normalize(origin - camera_position.xyz), normalize(normal_roughness.xyz),
                                              normal_roughness.w, pixel);
  const vec3 colour = seen_along_ray(lit_at(hit.point, hit.pixel, hit_position, hit_normal, footprint), hit.pixel,
                                     hit_position, hit_normal, ray);
  imageStore(reflection, pixel, vec4(hit.weight * colour, hit_distance));
}
