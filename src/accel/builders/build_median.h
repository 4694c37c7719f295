#pragma once
// Object-median BVH (OptiX 3/4 "MedianBvh"): split every node at the median centroid along the
// longest axis of its centroid box. Fast to build, balanced, ignores surface area.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"

namespace glint::accel {

Bvh build_median(const BuildInput& input, const BuildOptions& options = {});

}  // namespace glint::accel
