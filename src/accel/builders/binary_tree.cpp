#include "accel/builders/binary_tree.h"

#include "core/error.h"

namespace glint::accel::detail {

ParallelArray<SubtreeSummary> summarise_tree(const BinaryTree& tree, const BuildOptions& options) {
  ParallelArray<SubtreeSummary> summaries(tree.nodes.size(), kForOverwrite);  // the sweep visits every node
  visit_bottom_up(
      tree, [&](uint32_t leaf) { summaries[leaf] = summarise_leaf(tree.nodes[leaf].box, options); },
      [&](uint32_t node) {
        const TreeNode& n = tree.nodes[node];
        summaries[node] = summarise_interior(n.box, summaries[n.left], summaries[n.right], options);
      });
  return summaries;
}

void fit_interior_boxes(BinaryTree& tree) {
  visit_bottom_up(
      tree, [](uint32_t) {},
      [&](uint32_t node) {
        TreeNode& n = tree.nodes[node];
        n.box = tree.nodes[n.left].box;
        n.box.extend(tree.nodes[n.right].box);
      });
}

void check_build_input(const BuildInput& input, const BuildOptions& options, std::string_view builder) {
  if (input.boxes.size() != input.centroids.size())
    fail("accel: build_{}: {} boxes but {} centroids", builder, input.boxes.size(), input.centroids.size());
  if (input.boxes.size() >= (size_t{1} << 31))
    fail("accel: build_{}: {} primitives, at most 2^31 - 1", builder, input.boxes.size());
  if (options.max_leaf_size < 1) fail("accel: build_{}: max_leaf_size must be at least 1", builder);
}

BinaryTree make_leaves(const BuildInput& input, std::span<const uint32_t> prims) {
  BinaryTree tree;
  tree.leaf_count = static_cast<uint32_t>(prims.size());
  tree.nodes = ParallelArray<TreeNode>(prims.empty() ? 0 : 2 * prims.size() - 1);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, prims.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      tree.nodes[i].prim = prims[i];
      tree.nodes[i].box = input.boxes[prims[i]];
    }
  });
  if (prims.size() == 1) tree.root = 0;
  return tree;
}

}  // namespace glint::accel::detail
