#include "accel/trace.h"

#include "accel/traverse.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>

namespace glint::accel {

// Rays in a batch cost very different amounts; small grains let TBB balance them.
constexpr size_t kRayGrain = 64;

void check_traceable(const Bvh& bvh, size_t prim_count, const char* what) {
  if (!bvh.refittable) {
    // Leaves hold references (spatial splits): more slots than primitives, each one in range.
    uint32_t largest = 0;
    for (uint32_t prim : bvh.prim_indices) largest = std::max(largest, prim);
    if (bvh.prim_indices.size() < prim_count || (!bvh.prim_indices.empty() && largest >= prim_count))
      fail("accel: BVH with {} references up to primitive {} traced against {} {}", bvh.prim_indices.size(),
           largest, prim_count, what);
  } else if (bvh.prim_indices.size() != prim_count) {
    fail("accel: BVH built over {} primitives traced against {} {}", bvh.prim_indices.size(), prim_count, what);
  }
  if (bvh.depth > kMaxBvhDepth) fail("accel: BVH depth {} exceeds the traversal limit {}", bvh.depth, kMaxBvhDepth);
}

void check_batch_sizes(size_t ray_count, size_t result_count) {
  if (ray_count != result_count) fail("accel: {} rays but room for {} results", ray_count, result_count);
}

void trace_closest(const Bvh& bvh, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<Hit> hits) {
  check_traceable(bvh, mesh.triangle_count, "triangles");
  check_batch_sizes(rays.size(), hits.size());
  const BvhView view = bvh.view();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) hits[i] = trace_closest(view, mesh, rays[i]);
  });
}

void trace_any(const Bvh& bvh, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  check_traceable(bvh, mesh.triangle_count, "triangles");
  check_batch_sizes(rays.size(), occluded.size());
  const BvhView view = bvh.view();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) occluded[i] = trace_any(view, mesh, rays[i]) ? 1 : 0;
  });
}

}  // namespace glint::accel
