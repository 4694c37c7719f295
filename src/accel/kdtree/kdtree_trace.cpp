#include "accel/kdtree/kdtree_trace.h"

#include "accel/kdtree/kdtree_traverse.h"
#include "accel/trace.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint::accel {
namespace {

// Rays in a batch cost very different amounts; small grains let TBB balance them.
constexpr size_t kRayGrain = 64;

void check_tree(const KdTree& tree, const TriangleMesh& mesh) {
  if (tree.prim_count != mesh.triangle_count)
    fail("accel: kd-tree built over {} triangles traced against {} triangles", tree.prim_count, mesh.triangle_count);
  if (tree.depth > kMaxKdDepth) fail("accel: kd-tree depth {} exceeds the traversal limit {}", tree.depth, kMaxKdDepth);
}

}  // namespace

void trace_closest(const KdTree& tree, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<Hit> hits) {
  check_tree(tree, mesh);
  check_batch_sizes(rays.size(), hits.size());
  const KdTreeView view = tree.view();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) hits[i] = trace_closest(view, mesh, rays[i]);
  });
}

void trace_any(const KdTree& tree, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<uint8_t> occluded) {
  check_tree(tree, mesh);
  check_batch_sizes(rays.size(), occluded.size());
  const KdTreeView view = tree.view();
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), kRayGrain), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) occluded[i] = trace_any(view, mesh, rays[i]) ? 1 : 0;
  });
}

}  // namespace glint::accel
