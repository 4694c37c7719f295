#version 450 core
// Tile classification of `--reflections auto` (TileClassifyPass, docs/hybrid.md "auto"). One work
// group per 8x8 tile of the frame, before SSR:
// 1. Each pixel finds what SSR did for its surface last frame: its world position goes through the
//    previous frame's view-projection to the pixel q it covered then. If q's surface was reflective
//    (previous outcome != 0): where q's tile ran SSR last frame, SSR's failure mask at q is fresh
//    (failed or not); elsewhere q's previous outcome is carried on. The pixel's outcome is written
//    for the next frame: 0 not reflective, 1 reflective and unknown, 2 SSR succeeded, 3 SSR failed.
// 2. The tile counts its reflective, known and failed pixels and applies the tile rule
//    (include/tile_class_rule.glsl) with the host's thresholds.
// 3. The tile is appended to the SSR list (SSR only, SSR + rays) and the ray list (SSR + rays, rays
//    only); the lists' counts are the x sizes of the two indirect dispatches. Pixels of tiles that
//    do not run SSR get a zero reflection (SSR writes every pixel of the tiles it runs on).
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/tile_class_rule.glsl"

layout(binding = 0, rgba8) uniform readonly image2D albedo_reflectivity;
layout(binding = 1, rgba32f) uniform readonly image2D world_position;
layout(binding = 2, r8ui) uniform readonly uimage2D previous_failure_mask;
layout(binding = 3, r8ui) uniform readonly uimage2D previous_outcome;
layout(binding = 4, r8ui) uniform writeonly uimage2D outcome;
layout(binding = 5, rgba16f) uniform writeonly image2D reflection;

// render/tile_dispatch.h: lists, evidence (reflective, known, failed_known, class) and the dispatch block.
layout(std430, binding = 20) writeonly buffer TileLists { uint tile_lists[]; };
layout(std430, binding = 21) writeonly buffer TileEvidence { uvec4 tiles[]; };
layout(std430, binding = 22) readonly buffer PreviousTileEvidence { uvec4 previous_tiles[]; };
layout(std430, binding = 23) buffer TileDispatch {
  uint ssr_groups[3];
  uint ray_groups[3];
  uint class_tiles[4];
  uint class_pixels[4];
  uint rays_wanted;
};

uniform mat4 previous_view_projection;
uniform int have_history;
uniform int tile_columns;
uniform int ray_list_offset;  // first entry of the ray list in tile_lists
uniform float ssr_only_at_most;
uniform float rt_at_least;
uniform float min_known_fraction;
uniform int forced_class;  // >= 0: every tile with a reflective pixel gets it (the cost calibration's frame)

const uint kNotReflective = 0u, kUnknown = 1u, kSucceeded = 2u, kFailed = 3u;

shared uint group_reflective;
shared uint group_known;
shared uint group_failed;
shared uint group_class;

uint previous_result(vec3 position, ivec2 size) {
  if (have_history == 0) return kUnknown;
  const vec4 clip = previous_view_projection * vec4(position, 1.0);
  if (clip.w <= 0.0) return kUnknown;
  const vec2 screen = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size);
  if (any(lessThan(screen, vec2(0.0))) || any(greaterThanEqual(screen, vec2(size)))) return kUnknown;
  const ivec2 q = ivec2(screen);
  const uint before = imageLoad(previous_outcome, q).r;
  if (before == kNotReflective) return kUnknown;  // another surface was there: nothing known
  const uint previous_class = previous_tiles[(q.y / 8) * tile_columns + q.x / 8].w;
  if (previous_class == kTileSsrOnly || previous_class == kTileSsrFallback)
    return imageLoad(previous_failure_mask, q).r == 1u ? kFailed : kSucceeded;
  return before;
}

void main() {
  if (gl_LocalInvocationIndex == 0u) { group_reflective = 0u; group_known = 0u; group_failed = 0u; }
  barrier();

  const ivec2 size = imageSize(world_position);
  const ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  const bool inside = all(lessThan(pixel, size));
  if (inside) {
    const vec4 position = imageLoad(world_position, pixel);
    uint result = kNotReflective;
    if (position.w != 0.0 && imageLoad(albedo_reflectivity, pixel).a > 0.0) {
      result = previous_result(position.xyz, size);
      atomicAdd(group_reflective, 1u);
      if (result >= kSucceeded) atomicAdd(group_known, 1u);
      if (result == kFailed) atomicAdd(group_failed, 1u);
    }
    imageStore(outcome, pixel, uvec4(result));
  }
  barrier();

  const uint tile = gl_WorkGroupID.y * uint(tile_columns) + gl_WorkGroupID.x;
  if (gl_LocalInvocationIndex == 0u) {
    uint tile_class = classify_tile(group_reflective, group_known, group_failed, ssr_only_at_most, rt_at_least,
                                    min_known_fraction);
    if (forced_class >= 0 && group_reflective != 0u) tile_class = uint(forced_class);
    group_class = tile_class;
    tiles[tile] = uvec4(group_reflective, group_known, group_failed, tile_class);
    atomicAdd(class_tiles[tile_class], 1u);
    atomicAdd(class_pixels[tile_class], group_reflective);
    const uint entry = tile | (tile_class << 28);
    if (tile_class == kTileSsrOnly || tile_class == kTileSsrFallback) tile_lists[atomicAdd(ssr_groups[0], 1u)] = entry;
    if (tile_class == kTileSsrFallback || tile_class == kTileRtOnly)
      tile_lists[uint(ray_list_offset) + atomicAdd(ray_groups[0], 1u)] = entry;
  }
  barrier();
  if (inside && group_class != kTileSsrOnly && group_class != kTileSsrFallback) imageStore(reflection, pixel, vec4(0.0));
}
