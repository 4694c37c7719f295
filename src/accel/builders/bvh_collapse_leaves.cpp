#include "accel/builders/bvh_collapse_leaves.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <bit>
#include <vector>

namespace glint::accel::detail {
namespace {

// Levels of a balanced (halving) tree over `leaves` one-primitive leaves, before any collapsing.
uint32_t balanced_height(uint32_t leaves) { return 1 + static_cast<uint32_t>(std::bit_width(leaves - 1)); }

struct Rebalancer {
  BinaryTree& tree;
  std::vector<uint32_t> leaves;
  std::vector<uint32_t> interiors;

  void rebalance(uint32_t root) {
    leaves.clear();
    interiors.clear();
    std::vector<uint32_t> stack{root};
    while (!stack.empty()) {
      const uint32_t node = stack.back();
      stack.pop_back();
      const TreeNode& n = tree.nodes[node];
      if (n.is_leaf()) {
        leaves.push_back(node);
      } else {
        interiors.push_back(node);
        stack.push_back(n.right);
        stack.push_back(n.left);
      }
    }
    // interiors[0] is `root`, so the subtree keeps its place under its parent.
    uint32_t next_interior = 0;
    build(0, static_cast<uint32_t>(leaves.size()), tree.nodes[root].parent, next_interior);
  }

  uint32_t build(uint32_t begin, uint32_t end, uint32_t parent, uint32_t& next_interior) {
    if (end - begin == 1) {
      tree.nodes[leaves[begin]].parent = parent;
      return leaves[begin];
    }
    const uint32_t node = interiors[next_interior++];
    const uint32_t mid = begin + (end - begin) / 2;
    const uint32_t left = build(begin, mid, node, next_interior);
    const uint32_t right = build(mid, end, node, next_interior);
    TreeNode& n = tree.nodes[node];
    n.left = left;
    n.right = right;
    n.parent = parent;
    n.box = tree.nodes[left].box;
    n.box.extend(tree.nodes[right].box);
    return node;
  }
};

// At every visited node, level - 1 + balanced_height(prims) <= kMaxBvhDepth holds (true at the root
// for fewer than 2^31 primitives), so rebalancing it always fits; descend only while the children
// keep that promise.
void limit_depth(Rebalancer& rebalancer, std::span<const SubtreeSummary> summaries, uint32_t node, uint32_t level,
                 bool& changed) {
  if (level - 1 + summaries[node].height <= kMaxBvhDepth) return;
  const TreeNode& n = rebalancer.tree.nodes[node];
  const auto child_fits = [&](uint32_t child) {
    return level + balanced_height(summaries[child].prims) <= kMaxBvhDepth;
  };
  if (child_fits(n.left) && child_fits(n.right)) {
    const uint32_t left = n.left, right = n.right;
    limit_depth(rebalancer, summaries, left, level + 1, changed);
    limit_depth(rebalancer, summaries, right, level + 1, changed);
  } else {
    rebalancer.rebalance(node);
    changed = true;
  }
}

struct Flattener {
  const BinaryTree& tree;
  std::span<const SubtreeSummary> summaries;
  Bvh& bvh;
  uint32_t parallel_threshold;

  // Writes `node` at bvh.nodes[out]; its descendants (if it stays interior) fill
  // [descendants, descendants + out_nodes - 1): first its two children, then the left child's
  // descendants, then the right child's, which is the order top_down_builder produces.
  void emit(uint32_t node, uint32_t out, uint32_t descendants, uint32_t first_prim) const {
    const SubtreeSummary& summary = summaries[node];
    const TreeNode& n = tree.nodes[node];
    BvhNode& flat = bvh.nodes[out];
    flat.set_bounds(n.box);
    if (summary.collapse) {
      flat.first = first_prim;
      flat.prim_count = summary.prims;
      gather_prims(node, first_prim);
      return;
    }
    flat.first = descendants;
    flat.prim_count = 0;
    const SubtreeSummary& left = summaries[n.left];
    const uint32_t left_descendants = descendants + 2;
    const uint32_t right_descendants = left_descendants + left.out_nodes - 1;
    const uint32_t right_first_prim = first_prim + left.prims;
    if (summary.prims >= parallel_threshold) {
      tbb::task_group group;
      group.run([&] { emit(n.left, descendants, left_descendants, first_prim); });
      emit(n.right, descendants + 1, right_descendants, right_first_prim);
      group.wait();
    } else {
      emit(n.left, descendants, left_descendants, first_prim);
      emit(n.right, descendants + 1, right_descendants, right_first_prim);
    }
  }

  // The subtree's primitives, left to right, into consecutive prim_indices slots from `slot`;
  // returns the slot after the last. Recursion rather than a heap-allocated stack (this runs once
  // per leaf): a collapsed subtree has at most max_leaf_size primitives, so fewer levels than that.
  uint32_t gather_prims(uint32_t node, uint32_t slot) const {
    const TreeNode& n = tree.nodes[node];
    if (n.is_leaf()) {
      bvh.prim_indices[slot] = n.prim;
      return slot + 1;
    }
    return gather_prims(n.right, gather_prims(n.left, slot));
  }
};

}  // namespace

bool limit_tree_depth(BinaryTree& tree, std::span<const SubtreeSummary> summaries) {
  if (tree.leaf_count == 0 || summaries[tree.root].height <= kMaxBvhDepth) return false;
  Rebalancer rebalancer{tree, {}, {}};
  bool changed = false;
  limit_depth(rebalancer, summaries, tree.root, 1, changed);
  return changed;
}

Bvh flatten_tree(BinaryTree& tree, const BuildOptions& options, const std::string& builder) {
  if (tree.leaf_count == 0) return flatten_tree(tree, {}, options, builder);
  return flatten_tree(tree, summarise_tree(tree, options), options, builder);
}

Bvh flatten_tree(BinaryTree& tree, ParallelArray<SubtreeSummary> summaries, const BuildOptions& options,
                 const std::string& builder) {
  Bvh bvh;
  bvh.builder = builder;
  if (tree.leaf_count == 0) return bvh;
  if (limit_tree_depth(tree, summaries)) summaries = summarise_tree(tree, options);
  const SubtreeSummary& root = summaries[tree.root];
  bvh.nodes.resize(root.out_nodes);
  bvh.prim_indices.resize(tree.leaf_count);
  bvh.depth = root.height;
  const Flattener flattener{tree, summaries, bvh, std::max(options.parallel_threshold, 2u)};
  flattener.emit(tree.root, 0, 1, 0);
  return bvh;
}

}  // namespace glint::accel::detail
