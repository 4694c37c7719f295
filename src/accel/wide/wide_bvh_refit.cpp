#include "accel/wide/wide_bvh_refit.h"

#include "accel/ray.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace glint::accel {
namespace {

template <int N>
Aabb leaf_bounds(const WideBvh<N>& bvh, uint32_t first_block, uint32_t prim_count) {
  Aabb box;
  for (uint32_t slot = 0; slot < prim_count; ++slot) {
    const TriangleBlock<N>& block = bvh.blocks[first_block + slot / N];
    const uint32_t lane = slot % N;
    for (int corner = 0; corner < 3; ++corner)
      box.extend(vec3(block.v[corner][0][lane], block.v[corner][1][lane], block.v[corner][2][lane]));
  }
  return box;
}

template <int N>
Aabb node_bounds(const WideNode<N>& node) {
  Aabb box;
  for (int lane = 0; lane < N; ++lane)
    if (!node.is_empty(lane)) box.extend(node.child_bounds(lane));
  return box;
}

template <int N>
void refit_wide(WideBvh<N>& bvh, const TriangleMesh& mesh) {
  if (!bvh.refittable)
    fail("accel: refit: this wide BVH (from builder '{}') is not refittable; rebuild it instead", bvh.builder);
  if (mesh.triangle_count != bvh.prim_count)
    fail("accel: refit: mesh of {} triangles for a wide BVH over {}", mesh.triangle_count, bvh.prim_count);
  gather_wide_triangles(bvh, mesh);

  // Leaf lanes depend only on their blocks: all in parallel.
  std::vector<WideNode<N>>& nodes = bvh.nodes;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nodes.size(), 256), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      WideNode<N>& node = nodes[i];
      for (int lane = 0; lane < N; ++lane)
        if (!node.is_empty(lane) && node.is_leaf(lane))
          node.set_child_bounds(lane, leaf_bounds(bvh, node.child[lane], node.prim_count[lane]));
    }
  });
  // Children after parents: a reverse sweep finishes every child node before its parent's lane.
  for (size_t i = nodes.size(); i-- > 0;) {
    WideNode<N>& node = nodes[i];
    for (int lane = 0; lane < N; ++lane) {
      if (node.is_empty(lane) || node.is_leaf(lane)) continue;
      if (node.child[lane] <= i || node.child[lane] >= nodes.size())
        fail("accel: refit: wide node {} has a child at {}, not after it", i, node.child[lane]);
      node.set_child_bounds(lane, node_bounds(nodes[node.child[lane]]));
    }
  }
  bvh.bounds = nodes.empty() ? Aabb{} : node_bounds(nodes[0]);
}

}  // namespace

void refit(WideBvh4& bvh, const TriangleMesh& mesh) { refit_wide(bvh, mesh); }
void refit(WideBvh8& bvh, const TriangleMesh& mesh) { refit_wide(bvh, mesh); }

}  // namespace glint::accel
