#pragma once
// Linear BVH (Lauterbach et al. 2009; OptiX 3/4 "Lbvh") built as Karras 2012, "Maximizing
// parallelism in the construction of BVHs, octrees, and k-d trees": sort the centroids' Morton
// codes (morton.h, radix_sort.h), then every interior node of the binary radix tree over the sorted
// codes finds its key range and split independently, in parallel. Boxes are fitted bottom-up and the
// tree is flattened with SAH leaf collapsing (bvh_collapse_leaves.h). Fast to build; its quality
// is bounded by the Morton order, which trbvh and ploc improve on.
#include "accel/binary_tree.h"
#include "accel/build_options.h"
#include "accel/bvh.h"
#include "accel/morton.h"

namespace glint::accel {

Bvh build_lbvh(const BuildInput& input, const BuildOptions& options = {});

namespace detail {

// The Karras radix tree over order.codes (leaf i = primitive order.prims[i]; interior node i of the
// paper is nodes[leaf_count + i], the root is interior 0), with fitted boxes unless fit_boxes is
// false (then only the leaves have boxes: fit_and_summarise_tree fits them later in the same sweep
// that summarises). Equal codes are told apart by their position in the sorted order (the paper's
// index tie-break), so duplicates form balanced subtrees.
BinaryTree build_karras_tree(const BuildInput& input, const MortonOrder& order, bool fit_boxes = true);

// Morton sort plus build_karras_tree: the unflattened LBVH, which trbvh restructures.
BinaryTree build_lbvh_tree(const BuildInput& input);

}  // namespace detail
}  // namespace glint::accel
