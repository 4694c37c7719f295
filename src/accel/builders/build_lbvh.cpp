#include "accel/builders/build_lbvh.h"

#include "accel/builders/bvh_collapse_leaves.h"
#include "accel/builders/lbvh_layout.h"
#include "accel/builders/radix_tree_sweep.h"

#include <span>
#include <utility>

namespace glint::accel {
namespace detail {
namespace {

// The sweep into a BinaryTree. visit_leaf(leaf) and visit_interior(node) run once per node, children
// before parents, with the node's children, prim and box already written.
template <typename VisitLeaf, typename VisitInterior>
void build_binary_radix_tree(BinaryTree& tree, const BuildInput& input, const MortonOrder& order,
                             VisitLeaf&& visit_leaf, VisitInterior&& visit_interior) {
  const auto count = static_cast<uint32_t>(order.prims.size());
  tree.leaf_count = count;
  tree.root = kNoNode;
  if (count == 0) return;
  // Every field of every node is written once by the sweep, so nothing is initialised up front.
  tree.nodes = ParallelArray<TreeNode>(2 * size_t{count} - 1, kForOverwrite);
  tree.root = sweep_radix_tree(
      order.codes,
      [&](uint32_t leaf) {
        prefetch_box_ahead(input, order.prims, leaf);
        TreeNode& leaf_node = tree.nodes[leaf];
        leaf_node.prim = order.prims[leaf];
        leaf_node.box = input.boxes[leaf_node.prim];
        leaf_node.left = leaf_node.right = kNoNode;
        visit_leaf(leaf);
      },
      [&](uint32_t child, uint32_t parent, bool is_left_child) {
        tree.nodes[child].parent = parent;
        (is_left_child ? tree.nodes[parent].left : tree.nodes[parent].right) = child;
      },
      [&](uint32_t node, uint32_t, uint32_t) {
        TreeNode& interior = tree.nodes[node];
        interior.prim = kNoNode;
        interior.box = tree.nodes[interior.left].box;
        interior.box.extend(tree.nodes[interior.right].box);
        visit_interior(node);
      });
  tree.nodes[tree.root].parent = kNoNode;
}

}  // namespace

BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order) {
  BinaryTree tree;
  build_binary_radix_tree(tree, input, order, [](uint32_t) {}, [](uint32_t) {});
  return tree;
}

BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order, const BuildOptions& options,
                             ParallelArray<SubtreeSummary>& summaries) {
  summaries = ParallelArray<SubtreeSummary>(order.prims.empty() ? 0 : 2 * order.prims.size() - 1, kForOverwrite);
  BinaryTree tree;
  build_binary_radix_tree(
      tree, input, order,
      [&](uint32_t leaf) { summaries[leaf] = summarise_leaf(input.boxes[order.prims[leaf]], options); },
      [&](uint32_t node) {
        const TreeNode& n = tree.nodes[node];
        summaries[node] = summarise_interior(n.box, summaries[n.left], summaries[n.right], options);
      });
  return tree;
}

BinaryTree build_lbvh_tree(const BuildInput& input) { return build_karras_tree(input, sort_by_morton(input.centroids)); }

}  // namespace detail

Bvh build_lbvh(const BuildInput& input, const BuildOptions& options) {
  detail::check_build_input(input, options, "lbvh");
  MortonOrder order = sort_by_morton(input.centroids);
  const detail::LbvhSweep sweep = detail::sweep_lbvh(input, order, options);
  Bvh bvh;
  if (sweep.height > kMaxBvhDepth) {
    // Deeper than traversal allows (rare: 63-bit codes and the index tie-break allow about 95
    // levels): the BinaryTree path can rebalance.
    detail::ParallelArray<detail::SubtreeSummary> summaries;
    detail::BinaryTree binary = detail::build_karras_tree(input, order, options, summaries);
    bvh = detail::flatten_tree(binary, std::move(summaries), options, "lbvh");
  } else {
    bvh = detail::lay_out_lbvh(sweep, std::move(order.prims), "lbvh");
  }
  return bvh;
}

}  // namespace glint::accel
