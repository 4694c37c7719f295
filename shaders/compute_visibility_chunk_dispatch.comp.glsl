#version 450 core
// Compute rasteriser, between the large-triangle and tile dispatches (ComputeVisibilityPass): the
// tile dispatch's indirect size, one work group per record of the chunk list (more than one
// dimension takes wrap into y). One invocation: a dispatch of its own rather than atomics in every
// large-triangle invocation, which would all hit one word.
layout(local_size_x = 1) in;

#include "include/compute_visibility_buffers.glsl"

uniform uint chunk_capacity;

void main() {
  const uint records = min(chunk_count, chunk_capacity);
  tile_dispatch = uint[4](min(records, kMaxGroupsX), max((records + kMaxGroupsX - 1u) / kMaxGroupsX, 1u), 1u, 0u);
}
