#version 450 core
#include "include/compute_raster_extensions.glsl"
// Compute rasteriser, deferred triangles (ComputeVisibilityPass, both rounds): one invocation per
// triangle the per-triangle dispatch left (large on screen, or reaching in front of the near plane or
// out of the guard band). Round 0 clips it to the near plane and the guard band when needed, fans
// the polygon into pieces and writes them to the large-triangle list and their tiles to the chunk
// list for the tile dispatch; when a list is full, the invocation rasterises the pieces itself and
// marks the triangle kOverflowed, and does so again in round 1.
layout(local_size_x = 64) in;

#include "include/frame_constants.glsl"
#include "include/scene_geometry.glsl"
#include "include/scene_instances.glsl"
#include "include/compute_visibility_buffers.glsl"
#include "include/compute_raster.glsl"
#include "include/compute_raster_large.glsl"

uniform uint large_capacity;  // entries of large_triangles
uniform uint chunk_capacity;  // records of tile_chunks

// A triangle clipped by 5 planes: 3 corners, at most one more per plane; 2 spare for rounding on
// nearly degenerate polygons (writes beyond are dropped).
const int kMaxPolygon = 10;

// Signed distance to clipping plane `plane` (the near plane, then the guard band's sides): >= 0 inside.
float clip_distance(vec4 p, int plane) {
  precise float d;
  if (plane == 0) d = p.z + p.w;
  else if (plane == 1) d = kGuardBand * p.w - p.x;
  else if (plane == 2) d = kGuardBand * p.w + p.x;
  else if (plane == 3) d = kGuardBand * p.w - p.y;
  else d = kGuardBand * p.w + p.y;
  return d;
}

// Where an edge crosses a plane, always computed from its inside end: the two triangles sharing
// the edge get the same point, so their pieces still meet.
vec4 edge_crossing(vec4 inside, float d_inside, vec4 outside, float d_outside) {
  precise vec4 p = mix(inside, outside, d_inside / (d_inside - d_outside));
  return p;
}

// The triangle's polygon inside the near plane and the guard band (Sutherland-Hodgman); its size,
// 0 when nothing is left. A triangle that needs no clipping comes back as it is.
int clipped_polygon(uint triangle, out vec4 polygon[kMaxPolygon]) {
  vec4 corner[3];
  fetch_triangle(triangle, corner);
  for (int i = 0; i < 3; ++i) polygon[i] = corner[i];
  if (!needs_clipping(corner[0]) && !needs_clipping(corner[1]) && !needs_clipping(corner[2])) return 3;
  int size = 3;
  for (int plane = 0; plane < 5; ++plane) {
    vec4 clipped[kMaxPolygon];
    int count = 0;
    for (int i = 0; i < size; ++i) {
      const vec4 p = polygon[i], q = polygon[i + 1 == size ? 0 : i + 1];
      const float dp = clip_distance(p, plane), dq = clip_distance(q, plane);
      if (dp >= 0.0 && count < kMaxPolygon) clipped[count++] = p;
      if ((dp >= 0.0) != (dq >= 0.0) && count < kMaxPolygon)
        clipped[count++] = dp >= 0.0 ? edge_crossing(p, dp, q, dq) : edge_crossing(q, dq, p, dp);
    }
    polygon = clipped;
    size = count;
    if (size < 3) return 0;
  }
  return size;
}

// Round 0: a listed triangle's pieces go to the large-triangle list and their tiles to the chunk
// list, both reserved at once, so a triangle is either drawn by the tile dispatch or (a list full)
// by this invocation alone in both rounds, never half and half.
void rasterise_deferred(uint slot) {
  const uint entry = deferred[slot];
  const uint triangle = entry & ~kOverflowed;
  if (raster_round != 0u && (entry & kOverflowed) == 0u) return;  // the tile dispatch draws it
  vec4 polygon[kMaxPolygon];
  const int size = clipped_polygon(triangle, polygon);
  if (size < 3) return;
  const uint pieces = uint(size - 2);  // a fan around corner 0
  ScreenTriangle t;
  if (raster_round != 0u) {
    for (uint k = 0u; k < pieces; ++k)
      if (setup_triangle(polygon[0], polygon[k + 1u], polygon[k + 2u], t)) raster_box(t, triangle);
    return;
  }
  // The set-up is repeated below rather than kept: an array of pieces would live in local memory.
  uint chunks = 0u;
  for (uint k = 0u; k < pieces; ++k)
    if (setup_triangle(polygon[0], polygon[k + 1u], polygon[k + 2u], t)) chunks += chunk_count_of(tile_total(t.box));
  const uint first = atomicAdd(large_count, pieces);
  const uint first_chunk = atomicAdd(chunk_count, chunks);
  const bool listed = first + pieces <= large_capacity && first_chunk + chunks <= chunk_capacity;
  uint record = first_chunk;
  for (uint k = 0u; k < pieces; ++k) {
    if (!setup_triangle(polygon[0], polygon[k + 1u], polygon[k + 2u], t)) continue;
    if (!listed) {
      raster_box(t, triangle);
      continue;
    }
    large_triangles[first + k] = pack_large_triangle(t, triangle);
    const uint tiles = tile_total(t.box), per_chunk = chunk_tiles(tiles);
    for (uint tile = 0u; tile < tiles; tile += per_chunk) tile_chunks[record++] = uvec2(first + k, tile);
  }
  if (!listed) {
    // The tile dispatch runs over every record up to the count: the reserved ones say "nothing".
    for (uint r = first_chunk; r < min(first_chunk + chunks, chunk_capacity); ++r) tile_chunks[r] = uvec2(kNoEntry, 0u);
    deferred[slot] = entry | kOverflowed;
    atomicAdd(overflowed, 1u);
  }
}

void main() {
  const uint threads = gl_NumWorkGroups.x * gl_WorkGroupSize.x;
  for (uint slot = gl_GlobalInvocationID.x; slot < deferred_count; slot += threads) rasterise_deferred(slot);
}
