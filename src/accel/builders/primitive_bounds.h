#pragma once
// Builder input from triangles: one box per triangle and its centre as the centroid.
#include "accel/builders/build_options.h"
#include "accel/builders/parallel_array.h"
#include "accel/triangle_mesh.h"

#include <span>

namespace glint::accel {

// Parallel over triangles. Throws glint::Error when a vertex is not finite (a NaN would poison the
// SAH and every box above it).
PrimitiveBounds triangle_bounds(const TriangleMesh& mesh);

// Only the boxes (what refit needs), written to `boxes` (size == mesh.triangle_count).
void triangle_boxes(const TriangleMesh& mesh, std::span<Aabb> boxes);

namespace detail {

// triangle_bounds in arrays that the parallel loops filling them page in (parallel_array.h) rather
// than std::vectors zeroed by one thread, which on many cores took longer than some whole builds:
// what build_bvh(builder, mesh) builds from.
struct ScratchBounds {
  ParallelArray<Aabb> boxes;
  ParallelArray<vec3> centroids;

  BuildInput input() const { return {boxes, centroids}; }
};
ScratchBounds scratch_triangle_bounds(const TriangleMesh& mesh);

}  // namespace detail

// Half the surface area of a box (the SAH only needs ratios); 0 for an empty box.
GLINT_HOST_DEVICE inline float half_area(const Aabb& box) {
  const vec3 e = box.extent();
  return e.x * e.y + e.y * e.z + e.z * e.x;
}

}  // namespace glint::accel
