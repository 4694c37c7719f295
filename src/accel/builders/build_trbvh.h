#pragma once
// Treelet-restructuring BVH (Karras & Aila 2013, "Fast parallel construction of high-quality
// bounding volume hierarchies"; OptiX 3/4 "Trbvh"): an LBVH whose topology is then improved in a few
// bottom-up rounds. At every node, a treelet of up to 7 leaves is grown by repeatedly expanding the
// treelet leaf with the largest surface area; dynamic programming over all subsets of those leaves
// finds the treelet topology of least SAH cost (leaf collapsing included), which replaces the old
// one when it is cheaper. Nodes are processed in parallel once both children are done, so every
// treelet sees already optimised subtrees. Round r restructures nodes with at least 7 * 2^r
// primitives below (later rounds refine the upper levels, where most of the remaining cost is).
// Then the same leaf collapsing as lbvh.
#include "accel/builders/binary_tree.h"
#include "accel/builders/build_options.h"
#include "accel/bvh.h"

namespace glint::accel {

// options.treelet_rounds may be 0 (then the result equals build_lbvh's apart from the name).
Bvh build_trbvh(const BuildInput& input, const BuildOptions& options = {});

namespace detail {

inline constexpr uint32_t kTreeletLeaves = 7;  // the paper's choice: 2^7 subsets, all in registers on a GPU

// One round of treelet restructuring over the whole tree, in parallel. Treelets are formed at
// nodes with at least min_prims primitives below (smaller ones have few topologies to choose from
// and leaf collapsing decides most of them anyway). A treelet changes only when its new cost is
// lower, so the tree's SAH cost (summarise_tree's, with collapsing) never increases; the set of
// leaves and the boxes of treelet roots stay the same. Returns how many treelets changed.
uint32_t restructure_treelets(BinaryTree& tree, const BuildOptions& options, uint32_t min_prims);

}  // namespace detail
}  // namespace glint::accel
