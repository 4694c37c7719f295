#pragma once
// Structural checks of a wide BVH, for tests of every width and every binary builder it is
// collapsed from, and for debugging.
#include "accel/triangle_mesh.h"
#include "accel/wide/wide_bvh.h"

namespace glint::accel {

// Throws glint::Error naming the first broken invariant:
//  - no nodes and no blocks for an empty mesh; otherwise every node reached exactly once from the
//    root, every child node stored after its parent, depth <= kMaxBvhDepth and equal to bvh.depth
//  - lanes packed (no used lane after an empty one), at least two children per node except a root
//    whose single child is a leaf; empty lanes have empty boxes
//  - leaves own ceil(count / N) consecutive blocks, every block owned by exactly one leaf, real
//    lanes first then padding (kInvalidIndex) lanes; every triangle in exactly one real lane
//  - gathered corners equal the mesh's triangle; child boxes inside the parent's lane box (the
//    root's inside bvh.bounds); every triangle inside its leaf's lane box
template <int N>
void validate_wide_bvh(const WideBvh<N>& bvh, const TriangleMesh& mesh);

extern template void validate_wide_bvh<4>(const WideBvh<4>&, const TriangleMesh&);
extern template void validate_wide_bvh<8>(const WideBvh<8>&, const TriangleMesh&);

}  // namespace glint::accel
