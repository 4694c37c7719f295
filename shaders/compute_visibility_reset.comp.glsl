#version 450 core
#include "include/compute_raster_extensions.glsl"
// Compute rasteriser, first step (ComputeVisibilityPass::run): every pixel back to "nothing drawn"
// and the counters and indirect arguments to their start, in one dispatch. A dispatch rather than
// glClearNamedBufferData and glNamedBufferSubData: on an H100 those two took 0.24 ms at 1280x720,
// this is a few microseconds of stores.
layout(local_size_x = 256) in;

#include "include/compute_visibility_buffers.glsl"

uniform uint pixel_count;

void main() {
  const uint i = gl_GlobalInvocationID.x;
  if (i == 0u) {
    large_count = 0u;
    overflowed = 0u;
    chunk_count = 0u;
    deferred_count = 0u;
    tile_dispatch = uint[4](0u, 1u, 1u, 0u);      // compute_visibility_chunk_dispatch writes it
    deferred_dispatch = uint[4](0u, 1u, 1u, 0u);  // x counted up by the per-triangle dispatch
  }
  const uint threads = gl_NumWorkGroups.x * gl_WorkGroupSize.x;  // fewer than pixels on huge targets
  for (uint p = i; p < pixel_count; p += threads) {
#ifdef GLINT_RASTER_ONE_ROUND
    depth_pairs[p] = packUint2x32(uvec2(kNothingDrawn));
#else
    depth_keys[p] = kNothingDrawn;
    winners[p] = kNothingDrawn;
#endif
  }
}
