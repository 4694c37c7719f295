#include "accel/kdtree/kdtree_tlas.h"

#include "accel/trace.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint::accel {
namespace {

// As tlas_trace.cpp: small chunks balance incoherent rays across the cores.
constexpr size_t kRayGrain = 64;

KdTlasView checked_view(const Tlas& tlas, std::span<const KdBlas> blases, size_t ray_count, size_t result_count) {
  check_traceable(tlas.bvh, tlas.instances.size(), "instances");
  check_batch_sizes(ray_count, result_count);
  for (size_t i = 0; i < tlas.instances.size(); ++i)
    if (tlas.instances[i].blas >= blases.size())
      fail("accel: instance {} uses kd-tree BLAS {} of {}", i, tlas.instances[i].blas, blases.size());
  return {tlas.bvh.view(), tlas.instances.data(), blases.data()};
}

}  // namespace

KdBlas make_kd_blas(const KdTree& tree, const TriangleMesh& mesh) {
  if (tree.prim_count != mesh.triangle_count)
    fail("accel: kd-tree built over {} triangles used as the BLAS of a mesh of {}", tree.prim_count,
         mesh.triangle_count);
  if (tree.depth > kMaxKdDepth) fail("accel: kd-tree depth {} exceeds the traversal limit {}", tree.depth, kMaxKdDepth);
  return {tree.view(), mesh};
}

std::vector<Aabb> kd_blas_boxes(std::span<const KdBlas> blases) {
  std::vector<Aabb> boxes(blases.size());
  for (size_t b = 0; b < blases.size(); ++b)
    if (blases[b].tree.node_count != 0) boxes[b] = blases[b].tree.bounds;
  return boxes;
}

void trace_closest(const Tlas& tlas, std::span<const KdBlas> blases, std::span<const Ray> rays, std::span<Hit> hits) {
  const KdTlasView view = checked_view(tlas, blases, rays.size(), hits.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) hits[i] = trace_closest(view, rays[i]);
  });
}

void trace_any(const Tlas& tlas, std::span<const KdBlas> blases, std::span<const Ray> rays,
               std::span<uint8_t> occluded) {
  const KdTlasView view = checked_view(tlas, blases, rays.size(), occluded.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) occluded[i] = trace_any(view, rays[i]) ? 1 : 0;
  });
}

}  // namespace glint::accel
