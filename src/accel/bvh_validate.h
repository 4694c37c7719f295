#pragma once
// Structural checks every builder's output must pass; used by the tests of every builder and handy
// when debugging a new one.
#include "accel/bvh.h"

#include <cstdint>
#include <span>

namespace glint::accel {

// Throws glint::Error naming the first broken invariant:
//  - node count: 0 for no primitives, else reachable nodes == nodes.size() and
//    interior nodes == leaves - 1; every child index after its parent and in range
//  - every primitive referenced by exactly one leaf slot, every slot by exactly one leaf; for a
//    structure that is not refittable (spatial splits: leaves hold clipped references) every
//    primitive at least once and its box only overlapping, not inside, the leaf's box; such
//    builders add their own check of the references (validate_sbvh_references)
//  - leaf sizes in [1, max_leaf_size]
//  - child boxes inside their parent's box, primitive boxes inside their leaf's box
//  - depth <= kMaxBvhDepth and equal to bvh.depth
void validate_bvh(const Bvh& bvh, std::span<const Aabb> prim_boxes, uint32_t max_leaf_size);

}  // namespace glint::accel
