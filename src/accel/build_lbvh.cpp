#include "accel/build_lbvh.h"

#include "accel/bvh_collapse_leaves.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <bit>
#include <chrono>
#include <span>
#include <utility>

namespace glint::accel {
namespace detail {
namespace {

// Karras's delta(i, j): the length of the common prefix of keys i and j, where a key is the Morton
// code followed by the 32-bit position (so equal codes still differ).
struct CommonPrefix {
  std::span<const uint64_t> codes;

  int operator()(uint32_t i, uint32_t j) const {
    const uint64_t a = codes[i], b = codes[j];
    if (a != b) return std::countl_zero(a ^ b);
    return 64 + std::countl_zero(i ^ j);
  }
};

// Leaves ahead whose boxes the sweep prefetches.
inline constexpr uint32_t kBoxPrefetchDistance = 16;

// Apetrei 2014, "Fast and simple agglomerative LBVH construction": every leaf climbs towards the
// root; a node covering keys [first, last] joins the neighbour across whichever end shares the
// longer prefix with it. Interior node b (nodes[leaf_count + b]) is the one whose split lies between
// keys b and b + 1, so a node's parent is known from its range alone. The two children of a node
// meet at an atomic slot: the first to arrive leaves the far end of its range and stops, the second
// takes it and goes on with the union. In a radix tree the parent's split shares a longer prefix than
// the boundary on the node's other side (the keys beyond that one lack the parent's prefix), so this
// is exactly Karras's tree, with no binary searches and with each node visited once, after both of
// its children: boxes and anything else computed bottom-up come in the same sweep.
//
// Fills `tree`; visit_leaf(leaf) and visit_interior(node) run once per node, children before
// parents, with the node's children, prim and box already written.
template <typename VisitLeaf, typename VisitInterior>
void build_radix_tree(BinaryTree& tree, const BuildInput& input, const MortonOrder& order, VisitLeaf&& visit_leaf,
                      VisitInterior&& visit_interior) {
  const auto count = static_cast<uint32_t>(order.prims.size());
  tree.leaf_count = count;
  tree.root = kNoNode;
  if (count == 0) return;
  // Every field of every node is written once by the sweep, so nothing is initialised up front.
  tree.nodes = ParallelArray<TreeNode>(2 * size_t{count} - 1, kForOverwrite);
  // Far end + 1 of the first child to arrive, 0 while none has (value-initialised in parallel).
  ParallelArray<uint32_t> waiting(count - 1);
  const CommonPrefix delta{order.codes};
  const uint32_t last_key = count - 1;
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, 512), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t leaf = r.begin(); leaf != r.end(); ++leaf) {
      // The boxes are read in Morton order, so at random: fetching a few leaves ahead hides the
      // cache misses that were a third of this sweep.
      if (leaf + kBoxPrefetchDistance < count)
        __builtin_prefetch(&input.boxes[order.prims[leaf + kBoxPrefetchDistance]]);
      TreeNode& leaf_node = tree.nodes[leaf];
      leaf_node.prim = order.prims[leaf];
      leaf_node.box = input.boxes[leaf_node.prim];
      leaf_node.left = leaf_node.right = kNoNode;
      visit_leaf(leaf);
      uint32_t node = leaf, first = leaf, last = leaf;
      while (first != 0 || last != last_key) {
        const bool is_left_child = first == 0 || (last != last_key && delta(last, last + 1) > delta(first - 1, first));
        const uint32_t split = is_left_child ? last : first - 1;
        const uint32_t parent = count + split;
        tree.nodes[node].parent = parent;
        (is_left_child ? tree.nodes[parent].left : tree.nodes[parent].right) = node;
        // The second arrival must see everything the first one wrote below the parent (acquire,
        // against the first one's release). A sibling already there is seen by a plain acquire
        // load, with no locked instruction: a right child usually finds its left sibling done, as
        // leaves are taken left to right. Otherwise the exchange decides who goes on.
        const uint32_t far_end = is_left_child ? first : last;
        std::atomic_ref<uint32_t> slot(waiting[split]);
        uint32_t sibling_far_end = slot.load(std::memory_order_acquire);
        if (sibling_far_end == 0) {
          sibling_far_end = slot.exchange(far_end + 1, std::memory_order_acq_rel);
          if (sibling_far_end == 0) break;
        }
        (is_left_child ? last : first) = sibling_far_end - 1;
        node = parent;
        TreeNode& interior = tree.nodes[node];
        interior.prim = kNoNode;
        interior.box = tree.nodes[interior.left].box;
        interior.box.extend(tree.nodes[interior.right].box);
        visit_interior(node);
      }
      if (first == 0 && last == last_key) {
        tree.nodes[node].parent = kNoNode;
        tree.root = node;
      }
    }
  });
}

}  // namespace

BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order) {
  BinaryTree tree;
  build_radix_tree(tree, input, order, [](uint32_t) {}, [](uint32_t) {});
  return tree;
}

BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order, const BuildOptions& options,
                             ParallelArray<SubtreeSummary>& summaries) {
  summaries = ParallelArray<SubtreeSummary>(order.prims.empty() ? 0 : 2 * order.prims.size() - 1, kForOverwrite);
  BinaryTree tree;
  build_radix_tree(
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
  const auto start = std::chrono::steady_clock::now();
  detail::check_build_input(input, options, "lbvh");
  detail::ParallelArray<detail::SubtreeSummary> summaries;
  detail::BinaryTree tree =
      detail::build_karras_tree(input, sort_by_morton(input.centroids), options, summaries);
  Bvh bvh = detail::flatten_tree(tree, std::move(summaries), options, "lbvh");
  bvh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return bvh;
}

}  // namespace glint::accel
