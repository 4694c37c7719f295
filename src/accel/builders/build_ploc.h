#pragma once
// Parallel locally-ordered clustering (Meister & Bittner 2018, "Parallel locally-ordered
// clustering for bounding volume hierarchy construction"): agglomerative clustering made parallel
// by the Morton order. Every cluster starts as one primitive in Morton order; in each iteration every
// cluster finds its nearest neighbour among the options.ploc_radius clusters on either side (the
// distance is the surface area of the merged box), mutual nearest neighbours merge, and the
// surviving clusters are compacted with prefix sums, until one cluster is left. Then the same leaf
// collapsing as lbvh. Close to full-sweep SAH quality at a fraction of the cost.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"

namespace glint::accel {

// options.ploc_radius must be >= 1; glint::Error otherwise.
Bvh build_ploc(const BuildInput& input, const BuildOptions& options = {});

}  // namespace glint::accel
