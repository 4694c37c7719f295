#pragma once
// Internal to the bottom-up builders (lbvh, trbvh, ploc): turns their binary tree of one-primitive
// leaves into glint's flat Bvh. Subtrees become single leaves where the SAH says so (the rule is
// SubtreeSummary's in binary_tree.h), the layout is the one every builder keeps (sibling pairs
// adjacent, depth-first, children after their parent), and the depth is kept within kMaxBvhDepth.
#include "accel/builders/binary_tree.h"
#include "accel/bvh.h"

#include <span>
#include <string>

namespace glint::accel::detail {

// Where the tree (with leaf collapsing) would be deeper than kMaxBvhDepth, rebalances the shallowest
// subtrees that must change: their leaves, in their current left-to-right order, get a balanced
// tree (halving) that reuses the subtree's interior nodes. Returns whether anything changed. Rare:
// Morton trees are at most about 63 + 32 levels, and PLOC chains appear only on adversarial input.
bool limit_tree_depth(BinaryTree& tree, std::span<const SubtreeSummary> summaries);

// Flattens `tree` (rebalancing it first where limit_tree_depth must) into a Bvh with the leaves
// collapsed. Large subtrees are written by parallel TBB tasks at offsets known from the summaries,
// so the output is the same whatever the scheduling. Sets nodes, prim_indices, depth and builder.
Bvh flatten_tree(BinaryTree& tree, const BuildOptions& options, const std::string& builder);

// The same with the tree's summaries already computed (summarise_tree, or build_karras_tree's, of
// this tree and options), which saves a bottom-up sweep.
Bvh flatten_tree(BinaryTree& tree, ParallelArray<SubtreeSummary> summaries, const BuildOptions& options,
                 const std::string& builder);

}  // namespace glint::accel::detail
