#pragma once
// Internal to the bottom-up builders (lbvh, trbvh, ploc): the binary tree they build before it
// becomes a flat Bvh. One primitive per leaf, explicit parent links, and a parallel bottom-up sweep
// that visits a node only after both of its children (Karras 2012's atomic visit counters).
#include "accel/builders/build_options.h"
#include "accel/builders/parallel_array.h"
#include "accel/builders/primitive_bounds.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace glint::accel::detail {

inline constexpr uint32_t kNoNode = ~0u;

struct TreeNode {
  Aabb box;
  uint32_t left = kNoNode;    // kNoNode for a leaf
  uint32_t right = kNoNode;
  uint32_t parent = kNoNode;  // kNoNode for the root
  uint32_t prim = kNoNode;    // a leaf's primitive

  bool is_leaf() const { return left == kNoNode; }
};

// nodes[0, leaf_count) are the leaves, nodes[leaf_count, 2 leaf_count - 1) the interior nodes; the
// root is any of them (a lone leaf when leaf_count == 1).
struct BinaryTree {
  ParallelArray<TreeNode> nodes;
  uint32_t leaf_count = 0;
  uint32_t root = kNoNode;
};

// What the SAH with leaf collapsing makes of a subtree (Karras & Aila 2013, section 4):
//   cost(leaf of one primitive) = C_prim A
//   cost(n) = min(C_node A(n) + cost(left) + cost(right),      keep n interior
//                 C_prim A(n) N(n)  when N(n) <= max_leaf_size)  one leaf for the whole subtree
// with A the half surface area. Costs are not divided by the root area, so cost(root) / A(root)
// is exactly the SAH cost compute_stats reports for the flattened BVH. A leaf wins ties: it is
// never worse and keeps the tree smaller.
struct SubtreeSummary {
  double cost = 0.0;
  uint32_t prims = 0;      // primitives below
  uint32_t out_nodes = 0;  // nodes of the flattened subtree (1 when it becomes a leaf)
  uint32_t height = 0;     // levels of the flattened subtree
  bool collapse = false;   // becomes one leaf (always true for a single-primitive leaf)
};

inline double leaf_cost(const Aabb& box, const BuildOptions& options) {
  return double{options.intersection_cost} * half_area(box);
}

// The collapse rule of SubtreeSummary for a node with half area `area` over `prims` primitives and
// children of the given costs: the node's cost, and whether it becomes one leaf.
struct CollapseChoice {
  double cost;
  bool collapse;
};

inline CollapseChoice choose_collapse(double area, uint32_t prims, double left_cost, double right_cost,
                                      const BuildOptions& options) {
  const double interior_cost = double{options.traversal_cost} * area + left_cost + right_cost;
  if (prims <= options.max_leaf_size) {
    const double collapsed_cost = double{options.intersection_cost} * area * prims;
    if (collapsed_cost <= interior_cost) return {collapsed_cost, true};
  }
  return {interior_cost, false};
}

inline SubtreeSummary summarise_leaf(const Aabb& box, const BuildOptions& options) {
  return {leaf_cost(box, options), 1, 1, 1, true};
}

inline SubtreeSummary summarise_interior(const Aabb& box, const SubtreeSummary& left, const SubtreeSummary& right,
                                         const BuildOptions& options) {
  SubtreeSummary summary;
  summary.prims = left.prims + right.prims;
  const CollapseChoice choice = choose_collapse(half_area(box), summary.prims, left.cost, right.cost, options);
  summary.cost = choice.cost;
  summary.collapse = choice.collapse;
  summary.out_nodes = choice.collapse ? 1 : 1 + left.out_nodes + right.out_nodes;
  summary.height = choice.collapse ? 1 : 1 + std::max(left.height, right.height);
  return summary;
}

// Calls visit_leaf(leaf) for every leaf, then visit_interior(node) for every interior node once
// both of its children were visited, in parallel. Each thread climbs from its leaf and stops at a
// node whose other child is still in progress; the last one to arrive goes on. A visitor may
// rewrite anything below its node (treelet restructuring does) but not the node's parent link.
template <typename VisitLeaf, typename VisitInterior>
void visit_bottom_up(const BinaryTree& tree, VisitLeaf&& visit_leaf, VisitInterior&& visit_interior) {
  const uint32_t leaves = tree.leaf_count;
  // Zeroed by parallel chunks (ParallelArray), used through atomic_ref.
  ParallelArray<uint32_t> arrivals(leaves > 0 ? leaves - 1 : 0);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, leaves, 512), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t leaf = r.begin(); leaf != r.end(); ++leaf) {
      visit_leaf(leaf);
      uint32_t node = tree.nodes[leaf].parent;
      // acq_rel: the second arrival sees everything the first one wrote below the node.
      while (node != kNoNode &&
             std::atomic_ref<uint32_t>(arrivals[node - leaves]).fetch_add(1, std::memory_order_acq_rel) == 1) {
        visit_interior(node);
        node = tree.nodes[node].parent;
      }
    }
  });
}

// Summaries of every node (see SubtreeSummary), computed bottom-up in parallel.
ParallelArray<SubtreeSummary> summarise_tree(const BinaryTree& tree, const BuildOptions& options);

// Interior boxes as the union of their children's, bottom-up in parallel (leaf boxes must be set).
void fit_interior_boxes(BinaryTree& tree);

// The checks every builder makes of its input (sizes agree, fewer than 2^31 primitives,
// max_leaf_size >= 1); glint::Error naming the builder otherwise.
void check_build_input(const BuildInput& input, const BuildOptions& options, std::string_view builder);

// Leaves in input order: leaf i holds prims[i] with its box. The interior nodes are default
// (kNoNode links, empty boxes).
BinaryTree make_leaves(const BuildInput& input, std::span<const uint32_t> prims);

}  // namespace glint::accel::detail
