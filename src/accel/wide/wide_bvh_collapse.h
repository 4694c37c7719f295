#pragma once
// Collapsing a binary BVH into a 4- or 8-wide one (Wald, Benthin, Boulos, "Getting Rid of Packets",
// RT 2008; Embree's BVH4/BVH8): every wide node takes its binary node's two children and keeps
// opening the child with the largest surface area (the one a ray is most likely to enter, by the
// SAH's own argument) until it has N children or only leaves are left. The binary builder's SAH
// decisions are kept; only the levels between them disappear.
#include "accel/bvh.h"
#include "accel/triangle_mesh.h"
#include "accel/wide/wide_bvh.h"

#include <cstdint>

namespace glint::accel {

struct WideCollapseOptions {
  // A subtree of at most this many triangles whose leaves cover consecutive prim_indices slots
  // becomes one wide leaf: one SIMD triangle test instead of a node visit and several partly empty
  // blocks. kMergeToWidth means N (one full block); 0 keeps the binary leaves as they are.
  static constexpr uint32_t kMergeToWidth = 0xFFFFFFFFu;
  uint32_t merge_leaf_size = kMergeToWidth;
};

// glint::Error when the BVH was built over a different number of triangles, is deeper than
// kMaxBvhDepth, or breaks the node-order convention (children after their parent).
template <int N>
WideBvh<N> collapse_to_wide(const Bvh& bvh, const TriangleMesh& mesh, const WideCollapseOptions& options = {});

// Re-reads every block's triangles from the mesh by their original indices (after the vertices
// moved; the index buffer must be the same). Padding lanes repeat the last real triangle.
template <int N>
void gather_wide_triangles(WideBvh<N>& wide, const TriangleMesh& mesh);

extern template WideBvh<4> collapse_to_wide<4>(const Bvh&, const TriangleMesh&, const WideCollapseOptions&);
extern template WideBvh<8> collapse_to_wide<8>(const Bvh&, const TriangleMesh&, const WideCollapseOptions&);
extern template void gather_wide_triangles<4>(WideBvh<4>&, const TriangleMesh&);
extern template void gather_wide_triangles<8>(WideBvh<8>&, const TriangleMesh&);

}  // namespace glint::accel
