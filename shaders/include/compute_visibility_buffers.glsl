// The buffers of the compute rasteriser (ComputeVisibilityPass, src/render/compute_visibility_pass.*;
// binding numbers kDepthKeyBinding.. there). A shader uses the ones it needs; the others stay inactive.
// (Without GLINT_RASTER_ONE_ROUND; with it, depth_pairs holds both, see below.)
//   depth_keys  one per pixel (GL rows, y * width + x): the float bits of the nearest window depth
//               (non-negative floats order as their bits), 0xFFFFFFFF where nothing was drawn
//   winners     one per pixel: the draw-order number of the triangle kept there (instance's first
//               triangle + triangle in its mesh), 0xFFFFFFFF where nothing was drawn
//   deferred    draw-order numbers of the triangles the per-triangle dispatch left to the large one
//               (large on screen, or to be clipped); kOverflowed is set on those that found the
//               large-triangle list full and are rasterised by their own invocation
//   large_triangles  the large-triangle list
//   tile_chunks  the tile dispatch's work, one work group each: a large-triangle entry and the first
//               of the entry's 8x8-pixel tiles the group walks (chunk_tiles of them from there, in
//               compute_raster_large.glsl); kNoEntry in a record the large dispatch reserved but
//               could not use
//   counters    list sizes and the indirect dispatches' arguments
//   instance_first_triangle   instance i's triangles are [first[i], first[i + 1]) in draw order
//   touched     per triangle: the run stamp when round 0 found it nearest at some pixel (small
//               triangles only); round 1 skips the small triangles without this run's stamp
// GLINT_RASTER_ONE_ROUND declares neither winners nor touched: the pass binds no buffer there.

// A large triangle (or one piece of a clipped one), set up: corners in window space at 1/256 pixel,
// counter-clockwise; their window depths; the pixel box (x0, y0, x1, y1 inclusive, in the viewport).
struct LargeTriangle {
  ivec4 corners_ab;       // a.xy, b.xy
  ivec4 corner_c_number;  // c.xy, draw-order number, unused
  vec4 depths;            // a, b, c, unused
  ivec4 box;
};

#ifdef GLINT_RASTER_ONE_ROUND
// One 64-bit word per pixel instead: the depth key above the triangle's number, so one atomicMin
// keeps the nearest depth and, among equal depths, the first triangle (compute_raster_extensions.glsl).
// The second block reads the same buffer as 32-bit words: 2i is pixel i's triangle, 2i + 1 its key.
layout(std430, binding = 12) buffer DepthPairs { uint64_t depth_pairs[]; };
layout(std430, binding = 12) buffer DepthPairWords { uint depth_pair_words[]; };
#else
layout(std430, binding = 12) buffer DepthKeys { uint depth_keys[]; };
layout(std430, binding = 13) buffer Winners { uint winners[]; };
#endif
layout(std430, binding = 14) buffer LargeTriangles { LargeTriangle large_triangles[]; };
layout(std430, binding = 15) buffer TileChunks { uvec2 tile_chunks[]; };
layout(std430, binding = 16) buffer Counters {  // the twin of Counters in compute_visibility_pass.cpp
  uint large_count;     // entries asked for (beyond the capacity: some triangles overflowed)
  uint overflowed;      // triangles rasterised by their own invocation
  uint chunk_count;     // tile chunks asked for (beyond the chunk capacity: some triangles overflowed)
  uint deferred_count;
  uint tile_dispatch[4];      // glDispatchComputeIndirect's x, y, z (and padding)
  uint deferred_dispatch[4];  // x grows by one per 64 deferred triangles, up to kMaxGroupsX; y = z = 1
};
layout(std430, binding = 17) readonly buffer InstanceFirstTriangle { uint instance_first_triangle[]; };
layout(std430, binding = 18) buffer Deferred { uint deferred[]; };
#ifndef GLINT_RASTER_ONE_ROUND
layout(std430, binding = 19) buffer Touched { uint touched[]; };
#endif

const uint kNothingDrawn = 0xFFFFFFFFu;
const uint kOverflowed = 0x80000000u;  // in deferred[]; triangle numbers stay below it
const uint kNoEntry = 0xFFFFFFFFu;     // in tile_chunks[]: a record nobody draws
const uint kMaxGroupsX = 65535u;       // GL's guaranteed limit per dispatch dimension
const uint kDeferredGroupSize = 64u;   // compute_visibility_large.comp.glsl

// The instance whose triangles hold draw-order number `triangle` (instance_count >= 1).
uint instance_of_triangle(uint triangle, uint instance_count) {
  uint lo = 0u, hi = instance_count - 1u;
  while (lo < hi) {
    const uint mid = (lo + hi + 1u) >> 1;
    if (instance_first_triangle[mid] <= triangle) lo = mid; else hi = mid - 1u;
  }
  return lo;
}

// The triangle kept at pixel index i and the float bits of its depth (kNothingDrawn for both where
// nothing was drawn).
uint kept_triangle(uint i) {
#ifdef GLINT_RASTER_ONE_ROUND
  return depth_pair_words[2u * i];
#else
  return winners[i];
#endif
}
uint kept_depth_key(uint i) {
#ifdef GLINT_RASTER_ONE_ROUND
  return depth_pair_words[2u * i + 1u];
#else
  return depth_keys[i];
#endif
}

// The id the id draw writes for the triangle kept at pixel index i ({instance + 1, triangle in its
// mesh}; {0, 0} where nothing was drawn): what compute_visibility_ids.comp.glsl stores and the depth
// draw (compute_visibility_resolve.frag.glsl) writes again with the depth.
uvec2 kept_triangle_id(uint i, uint instance_count) {
  const uint triangle = kept_triangle(i);
  if (triangle == kNothingDrawn) return uvec2(0u);
  const uint instance = instance_of_triangle(triangle, instance_count);
  return uvec2(instance + 1u, triangle - instance_first_triangle[instance]);
}
