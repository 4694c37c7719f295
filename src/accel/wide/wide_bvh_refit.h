#pragma once
// Refit of a wide BVH after the mesh's vertices moved (same triangles, same index buffer): the
// leaf blocks are re-gathered from the mesh, then every child box is recomputed bottom-up over the
// SoA lanes. The topology stays, so quality degrades as the motion grows, as for the binary refit.
#include "accel/triangle_mesh.h"
#include "accel/wide/wide_bvh.h"

namespace glint::accel {

// glint::Error when the BVH is not refittable (collapsed from a structure with split references)
// or the mesh has a different triangle count.
void refit(WideBvh4& bvh, const TriangleMesh& mesh);
void refit(WideBvh8& bvh, const TriangleMesh& mesh);

}  // namespace glint::accel
