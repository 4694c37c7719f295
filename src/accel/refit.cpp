#include "accel/refit.h"

#include "accel/refit_tasks.h"
#include "core/error.h"

#include <atomic>

namespace glint::accel {
namespace {

// One depth-first pass: a leaf's box from its primitives, an interior node's from its children's,
// written on the way back up. Subtrees near the root run as parallel tasks (refit_tasks.h); below
// that a subtree is one task's sequential walk, which follows the builders' depth-first node order
// through memory.
template <typename LeafBox>
struct Refitter {
  std::span<BvhNode> nodes;
  std::span<const uint32_t> prim_indices;
  LeafBox leaf_box;  // (first slot, count) -> box of prim_indices[first, first + count)
  uint32_t task_levels;

  Aabb refit(uint32_t index, uint32_t level) const {
    BvhNode& node = nodes[index];
    Aabb box;
    if (node.is_leaf()) {
      box = leaf_box(node.first, node.prim_count);
    } else {
      if (node.left() <= index || node.right() >= nodes.size())
        fail("accel: refit: node {} has children at {}, not after it; refit needs children after parents", index,
             node.left());
      if (level >= kMaxBvhDepth) fail("accel: refit: the BVH is deeper than {} levels", kMaxBvhDepth);
      const auto [left, right] = detail::in_parallel_if(
          level < task_levels, [&] { return refit(node.left(), level + 1); },
          [&] { return refit(node.right(), level + 1); });
      box = left;
      box.extend(right);
    }
    node.set_bounds(box);
    return box;
  }
};

template <typename LeafBox>
void refit_nodes(Bvh& bvh, LeafBox leaf_box) {
  if (bvh.nodes.empty()) return;
  const Refitter<LeafBox> refitter{bvh.nodes, bvh.prim_indices, leaf_box, detail::refit_task_levels(bvh.nodes.size(), 2)};
  refitter.refit(0, 1);
}

void check_refittable(const Bvh& bvh, size_t prim_count) {
  if (!bvh.refittable)
    fail("accel: refit: this BVH (builder '{}') is not refittable; rebuild it instead", bvh.builder);
  if (prim_count != bvh.prim_indices.size())
    fail("accel: refit: {} primitive boxes for a BVH over {} primitives", prim_count, bvh.prim_indices.size());
}

}  // namespace

void refit(Bvh& bvh, std::span<const Aabb> prim_boxes) {
  check_refittable(bvh, prim_boxes.size());
  refit_nodes(bvh, [&](uint32_t first, uint32_t count) {
    Aabb box;
    for (uint32_t slot = first; slot != first + count; ++slot) box.extend(prim_boxes[bvh.prim_indices[slot]]);
    return box;
  });
}

void refit(Bvh& bvh, const TriangleMesh& mesh) {
  check_refittable(bvh, mesh.triangle_count);
  // The triangles are read straight into the leaf boxes: no array of primitive boxes in between.
  std::atomic<bool> finite{true};
  refit_nodes(bvh, [&](uint32_t first, uint32_t count) {
    Aabb box;
    bool leaf_finite = true;
    for (uint32_t slot = first; slot != first + count; ++slot) {
      const Triangle tri = mesh.triangle(bvh.prim_indices[slot]);
      leaf_finite = leaf_finite && is_finite(tri.v0) && is_finite(tri.v1) && is_finite(tri.v2);
      box.extend(tri.v0);
      box.extend(tri.v1);
      box.extend(tri.v2);
    }
    if (!leaf_finite) finite.store(false, std::memory_order_relaxed);
    return box;
  });
  if (!finite.load()) fail("accel: a triangle has a vertex that is not finite (NaN or infinity)");
}

}  // namespace glint::accel
