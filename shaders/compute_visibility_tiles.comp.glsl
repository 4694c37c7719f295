#version 450 core
#include "include/compute_raster_extensions.glsl"
// Compute rasteriser, large triangles (ComputeVisibilityPass, both rounds): one work group per record
// of the chunk list, one invocation per pixel of an 8x8-pixel tile; the group walks the record's
// tiles of its entry (chunk_tiles of them), so a triangle over the whole screen spreads over many
// groups and a few-tile one takes one group that loads the entry once.
layout(local_size_x = 8, local_size_y = 8) in;

#include "include/frame_constants.glsl"
#include "include/scene_geometry.glsl"
#include "include/scene_instances.glsl"
#include "include/compute_visibility_buffers.glsl"
#include "include/compute_raster.glsl"
#include "include/compute_raster_large.glsl"

uniform uint chunk_capacity;

void main() {
  const uint index = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  if (index >= min(chunk_count, chunk_capacity)) return;
  const uvec2 record = tile_chunks[index];
  if (record.x == kNoEntry) return;
  uint triangle;
  const ScreenTriangle t = unpack_large_triangle(large_triangles[record.x], triangle);
  const uint across = tiles_across(t.box), tiles = tile_total(t.box);
  const uint end = min(record.y + chunk_tiles(tiles), tiles);
  for (uint tile = record.y; tile < end; ++tile) {
    const ivec2 pixel = t.box.xy + kTileSize * ivec2(tile % across, tile / across) + ivec2(gl_LocalInvocationID.xy);
    if (all(lessThanEqual(pixel, t.box.zw))) raster_pixel(t, pixel, triangle);
  }
}
