#pragma once
// Structural and coverage checks of a kd-tree, for its tests and for debugging the builder.
#include "accel/kdtree/kdtree.h"
#include "accel/triangle_mesh.h"

namespace glint::accel {

// Throws glint::Error naming the first broken invariant:
//  - prim_count == mesh.triangle_count; bounds == the triangles' bounds; no nodes iff no triangles
//  - every interior node's below child is the next node and its above child lies after it; every
//    node reached exactly once; depth <= min(kMaxKdDepth, kdtree_depth_limit) and == tree.depth
//  - children partition their parent's cell: the split lies strictly inside the parent's cell on
//    its axis (the children are the two halves, so they cover it and overlap only in the plane)
//  - every prim_indices slot is used by exactly one leaf, every reference is a valid triangle whose
//    box overlaps the leaf's cell
//  - coverage: each triangle's vertices, edge midpoints and centroid each lie in the cell of a leaf
//    that references the triangle (so a ray hitting the triangle there reaches it)
void validate_kdtree(const KdTree& tree, const TriangleMesh& mesh, uint32_t depth_limit);

}  // namespace glint::accel
