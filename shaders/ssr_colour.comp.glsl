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

// The lit colour where the ray met the surface: bilinear between the pixel centres around `point`
// (inside `hit_pixel`), over the neighbours on the hit's surface only: a neighbour off the hit's
// plane by more than kSamePlane footprints (the hit pixel's world size) is another surface. (Its
// normal is not compared too: that cost 0.06 ms of SSR's 0.23 on an H100 for a few ten-thousandths
// of SSIM, docs/ssr.md.) The hit pixel's own colour alone was the reflection of the pixel centre, up
// to half a pixel from the hit: textured walls' reflections came out shifted (docs/ssr.md "Where
// the hit is").
const float kSamePlane = 0.5;
vec3 lit_at(vec2 point, ivec2 hit_pixel, vec3 hit_position, vec3 hit_normal, float footprint) {
  const vec2 q = clamp(point, vec2(hit_pixel), vec2(hit_pixel + 1)) - 0.5;
  const ivec2 base = ivec2(floor(q));
  const vec2 f = q - vec2(base);
  vec3 sum = vec3(0.0);
  float total = 0.0;
  for (int i = 0; i < 4; ++i) {
    const ivec2 corner = ivec2(i & 1, i >> 1);
    const ivec2 texel = clamp(base + corner, ivec2(0), screen_size - 1);
    const float w = mix(1.0 - f.x, f.x, float(corner.x)) * mix(1.0 - f.y, f.y, float(corner.y));
    const vec4 position = imageLoad(world_position, texel);
    const bool same_surface = texel == hit_pixel ||
                              (position.w != 0.0 &&
                               abs(dot(position.xyz - hit_position, hit_normal)) <= kSamePlane * footprint);
    if (w > 0.0 && same_surface) {
      sum += w * imageLoad(lit, texel).rgb;
      total += w;
    }
  }
  return total > 0.0 ? sum / total : imageLoad(lit, hit_pixel).rgb;
}

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
