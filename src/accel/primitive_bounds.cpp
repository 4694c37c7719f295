#include "accel/primitive_bounds.h"

#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>

namespace glint::accel {

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
  tbb::parallel_for(tbb::blocked_range<size_t>(0, bounds.boxes.size(), 4096), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) bounds.centroids[i] = bounds.boxes[i].center();
  });
  return bounds;
}

}  // namespace glint::accel
