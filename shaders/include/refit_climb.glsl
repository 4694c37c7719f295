// The gl backend's GPU refit (src/gl_rt/gl_refit.h, docs/ray-tracer.md "gl"): the part both of its
// kernels share, the climb from a leaf to the root by arrival counters (the algorithm of
// src/cuda/gpu_bvh_refit.cu). A leaf's invocation writes the leaf's box, then goes up through the
// parent links; at each node the first of the two children's invocations to arrive stops, and the
// second (its sibling's subtree is done) writes the node's box from both children's, sets the node's
// counter back to 0 for the next refit (nothing else arrives there in this one) and goes on.
// A climb is a chain of dependent round trips to L2, one chain per level, so each level waits on as
// few as it can: the climbing invocation carries its own child's box and reads only the sibling's,
// and reads the fixed topology (the node's children, its parent) before its arrival, not after
// (docs/perf.md "Twelfth round").
// The nodes and links take the trace's per-call bindings 25 and 26 (gl_rt_bindings.h): a refit is
// no trace. `coherent`: a box one invocation writes is read by another in the same dispatch, past
// the invocations' incoherent caches.

// accel::BvhNode, as gl_rt_structures.glsl reads it; only the bounds are written.
struct RefitNode {
  vec3 bounds_min;
  uint first;
  vec3 bounds_max;
  uint prim_count;
};
// The node array of every BVH (the TLAS's region first), read as a buffer texture by the traces.
layout(std430, binding = 25) coherent restrict buffer RefitNodes { RefitNode refit_nodes[]; };
// Per node of the node array: x its parent's index in its own BVH (kNoParent at a root), y its
// arrival counter (0 between refits). The host writes them when it lays a BVH out.
layout(std430, binding = 26) coherent restrict buffer RefitLinks { uvec2 refit_links[]; };

const uint kNoParent = 0xFFFFFFFFu;

// One invocation per node of the dispatch's BVHs: work groups of 64, in a grid of up to 65,535 x
// 65,535 groups (gl_refit.cpp), so that no scene is too large for one dispatch; the kernels take
// their index from grid_invocation().
#include "include/grid_invocation.glsl"

// The box of no point (accel's empty Aabb): +inf below, -inf above, so min/max with any box gives it.
void empty_box(out vec3 low, out vec3 high) {
  low = vec3(uintBitsToFloat(0x7F800000u));
  high = -low;
}

// Writes the box of leaf `leaf` (an index in the BVH whose region starts at node `base`) and climbs.
void refit_from_leaf(uint base, uint leaf, vec3 low, vec3 high) {
  refit_nodes[base + leaf].bounds_min = low;
  refit_nodes[base + leaf].bounds_max = high;
  uint child = leaf;
  for (uint node = refit_links[base + leaf].x; node != kNoParent;) {
    const uint left = refit_nodes[base + node].first;
    const uint parent = refit_links[base + node].x;
    // This invocation's boxes are visible before its arrival is.
    memoryBarrierBuffer();
    if (atomicAdd(refit_links[base + node].y, 1u) == 0u) return;  // the sibling's subtree is still going
    refit_links[base + node].y = 0u;
    // The sibling's box is read after the arrival that says it is written. The left child's box
    // comes first in min and max, as before and as accel::refit merges (min and max of a 0 and a -0
    // may depend on the order).
    memoryBarrierBuffer();
    const bool from_left = child == left;
    const uint sibling = base + (from_left ? left + 1u : left);
    const vec3 sibling_low = refit_nodes[sibling].bounds_min, sibling_high = refit_nodes[sibling].bounds_max;
    low = from_left ? min(low, sibling_low) : min(sibling_low, low);
    high = from_left ? max(high, sibling_high) : max(sibling_high, high);
    refit_nodes[base + node].bounds_min = low;
    refit_nodes[base + node].bounds_max = high;
    child = node;
    node = parent;
  }
}
