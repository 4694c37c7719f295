#include "accel/builders/primitive_bounds.h"

#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

namespace glint::accel {
namespace {

// centroids[i] = boxes[i].center(), in parallel.
void box_centres(std::span<const Aabb> boxes, std::span<vec3> centroids) {
  tbb::parallel_for(tbb::blocked_range<size_t>(0, boxes.size(), 4096), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) centroids[i] = boxes[i].center();
  });
}

}  // namespace

void triangle_boxes(const TriangleMesh& mesh, std::span<Aabb> boxes) {
  if (boxes.size() != mesh.triangle_count)
    fail("accel: {} boxes for {} triangles", boxes.size(), mesh.triangle_count);
  std::atomic<bool> finite{true};
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, mesh.triangle_count, 4096), [&](const auto& range) {
    bool range_finite = true;
    for (uint32_t i = range.begin(); i != range.end(); ++i) {
      const Triangle tri = mesh.triangle(i);
      range_finite = range_finite && is_finite(tri.v0) && is_finite(tri.v1) && is_finite(tri.v2);
      boxes[i] = tri.bounds();
    }
    if (!range_finite) finite.store(false, std::memory_order_relaxed);
  });
  if (!finite.load()) fail("accel: a triangle has a vertex that is not finite (NaN or infinity)");
}

PrimitiveBounds triangle_bounds(const TriangleMesh& mesh) {
  PrimitiveBounds bounds;
  bounds.boxes.resize(mesh.triangle_count);
  triangle_boxes(mesh, bounds.boxes);
  bounds.centroids.resize(mesh.triangle_count);
  box_centres(bounds.boxes, bounds.centroids);
  return bounds;
}

namespace detail {

ScratchBounds scratch_triangle_bounds(const TriangleMesh& mesh) {
  ScratchBounds bounds{ParallelArray<Aabb>(mesh.triangle_count, kForOverwrite),
                       ParallelArray<vec3>(mesh.triangle_count, kForOverwrite)};
  triangle_boxes(mesh, bounds.boxes);
  box_centres(bounds.boxes, bounds.centroids);
  return bounds;
}

}  // namespace detail

}  // namespace glint::accel
