#pragma once
// Binned SAH BVH (Wald 2007; OptiX 3/4 "Bvh"): at every node, bin the centroids along each axis
// into options.bins slabs, evaluate the surface area heuristic at every bin boundary and take the
// cheapest split, or make a leaf when that is cheaper and the node fits in max_leaf_size.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"

namespace glint::accel {

// options.bins must be in [2, 256]; glint::Error otherwise.
Bvh build_sah(const BuildInput& input, const BuildOptions& options = {});

}  // namespace glint::accel
