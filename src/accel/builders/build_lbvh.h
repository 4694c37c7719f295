#pragma once
// Linear BVH (Lauterbach et al. 2009; OptiX 3/4 "Lbvh"): the binary radix tree over the centroids'
// sorted Morton codes (morton.h, radix_sort.h) of Karras 2012, "Maximizing parallelism in the
// construction of BVHs, octrees, and k-d trees", with SAH leaf collapsing. build_lbvh makes the tree,
// its collapse and its flat layout in one sweep over the sorted keys (lbvh_layout.h); the tree as a
// BinaryTree, for trbvh, comes from Apetrei 2014's bottom-up sweep, "Fast and simple agglomerative
// LBVH construction" (one parallel sweep that also fits the boxes and the collapse costs), flattened
// by bvh_collapse_leaves.h. Fast to build; its quality is bounded by the Morton order, which trbvh
// and ploc improve on.
#include "accel/builders/binary_tree.h"
#include "accel/builders/build_options.h"
#include "accel/bvh.h"
#include "accel/builders/morton.h"

namespace glint::accel {

Bvh build_lbvh(const BuildInput& input, const BuildOptions& options = {});

namespace detail {

// The Karras radix tree over order.codes (leaf i = primitive order.prims[i]; interior nodes are
// nodes[leaf_count + b], b the position of their split: the left child ends at key b), with fitted
// boxes. Equal codes are told apart by their position in the sorted order (the paper's index
// tie-break), so duplicates form balanced subtrees. Built bottom-up in one parallel sweep (Apetrei
// 2014, build_lbvh.cpp), which gives the same tree as Karras's per-node searches.
BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order);

// The same, with every node's SubtreeSummary (binary_tree.h) for `options` computed in the same
// sweep into `summaries`: what flatten_tree needs, without a second bottom-up pass.
BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order, const BuildOptions& options,
                             ParallelArray<SubtreeSummary>& summaries);

// Morton sort plus build_karras_tree: the unflattened LBVH, which trbvh restructures.
BinaryTree build_lbvh_tree(const BuildInput& input);

}  // namespace detail
}  // namespace glint::accel
