#include "accel/refit.h"

#include "accel/builders/parallel_array.h"
#include "accel/builders/primitive_bounds.h"
#include "core/error.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <vector>

namespace glint::accel {
namespace {

// Every builder lays nodes out depth-first with sibling pairs (a node's two children, then one
// child's descendants, then the other's: the left child's first, except lbvh, which puts the
// right child's first, lbvh_layout.h), so a subtree's descendants are one contiguous range of the
// array. The refit cuts the tree into such subtrees near the root, sweeps each one's range in
// reverse (children before parents, in memory order) as a parallel task, then finishes the few
// nodes above the cut serially. A tree in another order (children after parents is all refit
// promises its callers) gets one serial reverse sweep instead.
struct Subtree {
  uint32_t root;
  uint32_t begin, end;  // the root's descendants: nodes[begin, end)
};

// Splits the tree into subtrees of at most `limit` descendants and the nodes above them (`top`, in
// breadth-first order, parents before children). False when the layout is not the depth-first one.
bool cut_tree(std::span<const BvhNode> nodes, size_t limit, std::vector<uint32_t>& top, std::vector<Subtree>& subtrees) {
  std::vector<Subtree> queue{{0, 1, static_cast<uint32_t>(nodes.size())}};
  for (size_t next = 0; next < queue.size(); ++next) {
    const Subtree subtree = queue[next];
    const BvhNode& node = nodes[subtree.root];
    if (node.is_leaf() || subtree.end - subtree.begin <= limit) {
      if (node.is_leaf() && subtree.begin != subtree.end) return false;
      subtrees.push_back(subtree);
      continue;
    }
    const uint32_t left = node.left(), right = node.right();
    if (left != subtree.begin || right + 1 > subtree.end) return false;
    // After the pair come the descendants of one child, then the other's (a leaf has none): the
    // right child's first when they start before the left child's.
    const bool right_first = !nodes[right].is_leaf() && (nodes[left].is_leaf() || nodes[right].first < nodes[left].first);
    const uint32_t first_child = right_first ? right : left, second_child = right_first ? left : right;
    if (!nodes[first_child].is_leaf() && nodes[first_child].first != right + 1) return false;
    const uint32_t second_begin = nodes[second_child].is_leaf() ? subtree.end : nodes[second_child].first;
    if (second_begin < right + 1 || second_begin > subtree.end) return false;
    top.push_back(subtree.root);
    queue.push_back({first_child, right + 1, second_begin});
    queue.push_back({second_child, second_begin, subtree.end});
  }
  return true;
}

template <typename LeafBox>
struct Refitter {
  std::span<BvhNode> nodes;
  const LeafBox& leaf_box;  // (first slot, count) -> box of those primitives

  void refit_node(uint32_t i) const {
    BvhNode& node = nodes[i];
    if (node.is_leaf()) {
      node.set_bounds(leaf_box(node.first, node.prim_count));
      return;
    }
    Aabb box = nodes[node.left()].bounds();
    box.extend(nodes[node.right()].bounds());
    node.set_bounds(box);
  }

  // Reverse sweep over nodes[begin, end); false (nothing reliable written) when a child is not after
  // its parent inside the range.
  bool sweep(uint32_t begin, uint32_t end) const {
    for (uint32_t i = end; i-- > begin;) {
      const BvhNode& node = nodes[i];
      if (!node.is_leaf() && (node.left() <= i || node.right() >= end)) return false;
      refit_node(i);
    }
    return true;
  }
};

template <typename LeafBox>
void refit_nodes(Bvh& bvh, const LeafBox& leaf_box) {
  const auto count = static_cast<uint32_t>(bvh.nodes.size());
  if (count == 0) return;
  const Refitter<LeafBox> refitter{bvh.nodes, leaf_box};
  // Several subtrees per thread, so that stealing evens out their sizes; none below 1024 nodes.
  const size_t limit = std::max<size_t>(1024, count / (8 * static_cast<size_t>(tbb::this_task_arena::max_concurrency())));
  std::vector<uint32_t> top;
  std::vector<Subtree> subtrees;
  std::atomic<bool> in_order{cut_tree(bvh.nodes, limit, top, subtrees)};
  if (in_order.load()) {
    tbb::parallel_for(size_t{0}, subtrees.size(), [&](size_t s) {
      if (!refitter.sweep(subtrees[s].begin, subtrees[s].end)) in_order.store(false, std::memory_order_relaxed);
      else refitter.refit_node(subtrees[s].root);
    });
  }
  if (!in_order.load()) {
    if (!refitter.sweep(0, count))
      fail("accel: refit: a node has children before it or past the end; refit needs children after parents");
    return;
  }
  for (size_t i = top.size(); i-- > 0;) refitter.refit_node(top[i]);
}

}  // namespace

bool detail::refits_in_parallel(const Bvh& bvh) {
  std::vector<uint32_t> top;
  std::vector<Subtree> subtrees;
  return bvh.nodes.empty() || cut_tree(bvh.nodes, 1, top, subtrees);
}

namespace {

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
  // Triangle boxes first, in triangle order (sequential reads of the index buffer, in parallel),
  // then the sweeps read one box per primitive: faster than gathering each leaf's triangles through
  // the index buffer in leaf order, measured with the deforming dinosaurs.
  detail::ParallelArray<Aabb> boxes(mesh.triangle_count, detail::kForOverwrite);
  triangle_boxes(mesh, boxes);
  refit(bvh, boxes);
}

}  // namespace glint::accel
