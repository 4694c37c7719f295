#include "accel/refit.h"

#include "accel/primitive_bounds.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <vector>

namespace glint::accel {

void refit(Bvh& bvh, std::span<const Aabb> prim_boxes) {
  if (!bvh.refittable)
    fail("accel: refit: this BVH (builder '{}') is not refittable; rebuild it instead", bvh.builder);
  if (prim_boxes.size() != bvh.prim_indices.size())
    fail("accel: refit: {} primitive boxes for a BVH over {} primitives", prim_boxes.size(), bvh.prim_indices.size());

  // Leaves depend only on their primitives: all in parallel.
  std::vector<BvhNode>& nodes = bvh.nodes;
  tbb::parallel_for(tbb::blocked_range<size_t>(0, nodes.size(), 1024), [&](const auto& range) {
    for (size_t i = range.begin(); i != range.end(); ++i) {
      BvhNode& node = nodes[i];
      if (!node.is_leaf()) continue;
      Aabb box;
      for (uint32_t slot = node.first; slot != node.first + node.prim_count; ++slot)
        box.extend(prim_boxes[bvh.prim_indices[slot]]);
      node.set_bounds(box);
    }
  });
  // Children are stored after their parents, so a reverse sweep sees both children of a node
  // before the node itself. Two min/max per node: memory-bound, a parallel level order would not pay.
  for (size_t i = nodes.size(); i-- > 0;) {
    BvhNode& node = nodes[i];
    if (node.is_leaf()) continue;
    if (node.left() <= i || node.right() >= nodes.size())
      fail("accel: refit: node {} has children at {}, not after it; the reverse sweep needs that order", i, node.left());
    Aabb box = nodes[node.left()].bounds();
    box.extend(nodes[node.right()].bounds());
    node.set_bounds(box);
  }
}

void refit(Bvh& bvh, const TriangleMesh& mesh) {
  if (!bvh.refittable)
    fail("accel: refit: this BVH (builder '{}') is not refittable; rebuild it instead", bvh.builder);
  std::vector<Aabb> boxes(mesh.triangle_count);
  triangle_boxes(mesh, boxes);
  refit(bvh, boxes);
}

}  // namespace glint::accel
