#pragma once
// No acceleration (OptiX 3/4 "NoAccel"): one leaf holding every primitive, so traversal tests
// them all. The reference the other builders are checked against, behind the same interface.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"

namespace glint::accel {

// BuildOptions are accepted for a uniform interface and ignored (the leaf exceeds max_leaf_size).
Bvh build_none(const BuildInput& input, const BuildOptions& options = {});

}  // namespace glint::accel
