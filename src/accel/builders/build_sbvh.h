#pragma once
// SBVH: SAH BVH with spatial splits (Stich, Friedrich, Dietrich, "Spatial Splits in Bounding
// Volume Hierarchies", HPG 2009; OptiX 3/4 "Sbvh"). At every node the builder tries binned object
// splits as build_sah does and, where the two children of the best object split overlap by more
// than alpha times the root's area, also spatial splits: the node box is cut into slabs and every
// reference is clipped to the slabs it straddles (chopped binning), so a long triangle can go to
// both children with a smaller box on each side. Straddling references are "unsplit" (sent whole to
// one side) when that is cheaper (the paper's section 4.4). Leaves hold REFERENCES: one triangle
// may appear in several leaves, so prim_indices is longer than the primitive count and the BVH is
// not refittable (a moved vertex invalidates every clipped box).
//
// Geometry: clipping a triangle to a slab needs its vertices, so the triangle overload is the real
// SBVH. The BuildInput overload (what build_bvh(BvhBuilder::sbvh, BuildInput) and the TLAS call)
// has boxes only and clips the boxes themselves; it is correct, only the split boxes are looser.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"
#include "accel/triangle_mesh.h"

#include <cstdint>

namespace glint::accel {

struct SbvhOptions {
  // Spatial splits are tried only where the overlap of the best object split's children has more
  // than alpha times the root's surface area (the paper's alpha; 1 = never, 0 = always).
  float alpha = 1e-5f;
  // At most reference_budget * primitive count references in all leaves (>= 1). Each node hands
  // its unspent extra references to its children in proportion to their sizes, so the result does
  // not depend on how TBB schedules the subtrees.
  float reference_budget = 2.0f;
  uint32_t spatial_bins = 32;  // slabs per axis for spatial splits, 2..256
};

// Triangle clipping; boxes and centroids come from the mesh (their time is included in build_ms).
// glint::Error on a non-finite vertex or invalid options.
Bvh build_sbvh(const TriangleMesh& mesh, const BuildOptions& options = {}, const SbvhOptions& sbvh = {});

// Box clipping, for primitives known only by their boxes (e.g. TLAS instances).
Bvh build_sbvh(const BuildInput& input, const BuildOptions& options = {}, const SbvhOptions& sbvh = {});

// The SBVH-specific half of validation (validate_bvh checks the structure): the reference count is
// within budget (ceil(reference_budget * triangles), 0 to skip) and every triangle is covered by
// the boxes of the leaves that reference it: its vertices, edge midpoints and centroid each lie in
// one of them. glint::Error naming the first failure.
void validate_sbvh_references(const Bvh& bvh, const TriangleMesh& mesh, float reference_budget);

}  // namespace glint::accel
