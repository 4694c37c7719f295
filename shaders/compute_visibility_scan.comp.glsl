#version 450 core
// Compute rasteriser, between the triangle and tile dispatches (ComputeVisibilityPass): one work
// group numbers the 8x8-pixel tiles of every large-triangle entry (tile_starts: exclusive prefix
// sums over the list in list order) and writes the tile dispatch's indirect arguments.
layout(local_size_x = 1024) in;

#include "include/compute_visibility_buffers.glsl"

uniform uint large_capacity;

const int kTileSize = 8;  // compute_visibility_tiles.comp.glsl's work group side

uint entry_tiles(uint entry) {
  const ivec4 box = large_triangles[entry].box;
  if (box.x > box.z || box.y > box.w) return 0u;
  return uint((box.z - box.x + kTileSize) / kTileSize) * uint((box.w - box.y + kTileSize) / kTileSize);
}

shared uint sums[1024];  // one per invocation

void main() {
  const uint id = gl_LocalInvocationID.x, threads = gl_WorkGroupSize.x;
  const uint count = min(large_count, large_capacity);
  const uint per_thread = (count + threads - 1u) / threads;
  const uint begin = min(id * per_thread, count), end = min(begin + per_thread, count);
  uint own = 0u;
  for (uint e = begin; e < end; ++e) own += entry_tiles(e);
  sums[id] = own;
  memoryBarrierShared();
  barrier();
  for (uint offset = 1u; offset < threads; offset <<= 1) {  // inclusive scan (Hillis-Steele)
    const uint add = id >= offset ? sums[id - offset] : 0u;
    memoryBarrierShared();
    barrier();
    sums[id] += add;
    memoryBarrierShared();
    barrier();
  }
  uint start = sums[id] - own;
  for (uint e = begin; e < end; ++e) {
    tile_starts[e] = start;
    start += entry_tiles(e);
  }
  if (id == threads - 1u) {
    const uint total = sums[id];
    tile_count = total;
    tile_dispatch[0] = min(total, kMaxGroupsX);
    tile_dispatch[1] = max((total + kMaxGroupsX - 1u) / kMaxGroupsX, 1u);
    tile_dispatch[2] = 1u;
  }
}
