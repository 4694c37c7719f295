#version 450 core
#include "include/compute_raster_extensions.glsl"
// Compute rasteriser, large triangles (ComputeVisibilityPass, both rounds): one work group per
// 8x8-pixel tile of each large-triangle entry's pixel box (numbered by the scan), one invocation
// per pixel, so a triangle over the whole screen spreads over as many groups as it has tiles.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/scene_geometry.glsl"
#include "include/scene_instances.glsl"
#include "include/compute_visibility_buffers.glsl"
#include "include/compute_raster.glsl"
#include "include/compute_raster_large.glsl"

uniform uint large_capacity;

const int kTileSize = 8;

void main() {
  const uint tile = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  if (tile >= tile_count) return;
  // The entry holding the tile: the last whose first tile is not after it (entries without tiles
  // share their start with the next one and are skipped that way).
  uint lo = 0u, hi = min(large_count, large_capacity) - 1u;
  while (lo < hi) {
    const uint mid = (lo + hi + 1u) >> 1;
    if (tile_starts[mid] <= tile) lo = mid; else hi = mid - 1u;
  }
  uint triangle;
  const ScreenTriangle t = unpack_large_triangle(large_triangles[lo], triangle);
  const uint in_entry = tile - tile_starts[lo];
  const uint tiles_x = uint((t.box.z - t.box.x + kTileSize) / kTileSize);
  const ivec2 pixel = t.box.xy + kTileSize * ivec2(in_entry % tiles_x, in_entry / tiles_x) + ivec2(gl_LocalInvocationID.xy);
  if (any(greaterThan(pixel, t.box.zw))) return;
  raster_pixel(t, pixel, triangle);
}
