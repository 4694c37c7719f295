#include "accel/build_lbvh.h"

#include "accel/bvh_collapse_leaves.h"
#include "accel/radix_tree_split.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <span>
#include <utility>

namespace glint::accel {
namespace detail {
namespace {

// Karras's delta(i, j): the length of the common prefix of keys i and j, where a key is the Morton
// code followed by the 32-bit position (so equal codes still differ); -1 outside [0, count).
struct CommonPrefix {
  std::span<const uint64_t> codes;
  int64_t count;

  int operator()(int64_t i, int64_t j) const {
    if (j < 0 || j >= count) return -1;
    const uint64_t a = codes[static_cast<size_t>(i)], b = codes[static_cast<size_t>(j)];
    if (a != b) return std::countl_zero(a ^ b);
    return 64 + std::countl_zero(static_cast<uint32_t>(i ^ j));
  }
};

// One interior node of the radix tree (accel/radix_tree_split.h, shared with the GPU LBVH).
void build_interior(BinaryTree& tree, const CommonPrefix& delta, int64_t i) {
  const RadixTreeNode range = radix_tree_node(delta, i);
  const auto leaves = static_cast<int64_t>(tree.leaf_count);
  const auto node = static_cast<uint32_t>(leaves + i);
  const auto left = static_cast<uint32_t>(range.left_child(leaves));
  const auto right = static_cast<uint32_t>(range.right_child(leaves));
  tree.nodes[node].left = left;
  tree.nodes[node].right = right;
  // Every node has exactly one parent, so these writes never race.
  tree.nodes[left].parent = node;
  tree.nodes[right].parent = node;
}

}  // namespace

BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order, bool fit_boxes) {
  BinaryTree tree = make_leaves(input, order.prims);
  const uint32_t count = tree.leaf_count;
  if (count < 2) return tree;
  tree.root = count;
  const CommonPrefix delta{order.codes, count};
  tbb::parallel_for(tbb::blocked_range<int64_t>(0, int64_t{count} - 1, 1024), [&](const tbb::blocked_range<int64_t>& r) {
    for (int64_t i = r.begin(); i != r.end(); ++i) build_interior(tree, delta, i);
  });
  if (fit_boxes) fit_interior_boxes(tree);
  return tree;
}

BinaryTree build_lbvh_tree(const BuildInput& input) {
  return build_karras_tree(input, sort_by_morton(input.centroids));
}

}  // namespace detail

Bvh build_lbvh(const BuildInput& input, const BuildOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  detail::check_build_input(input, options, "lbvh");
  detail::BinaryTree tree = detail::build_karras_tree(input, sort_by_morton(input.centroids), false);
  detail::ParallelArray<detail::SubtreeSummary> summaries = detail::fit_and_summarise_tree(tree, options);
  Bvh bvh = detail::flatten_tree(tree, std::move(summaries), options, "lbvh");
  bvh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return bvh;
}

}  // namespace glint::accel
