#pragma once
// Refit: after primitives moved (same primitives, same count), recompute every box bottom-up and
// keep the topology. Much cheaper than a rebuild; quality degrades as the motion grows.
#include "accel/bvh.h"
#include "accel/triangle_mesh.h"

#include <span>

namespace glint::accel {

// prim_boxes[i] is the new box of primitive i. glint::Error when bvh.refittable is false (e.g. a
// structure with spatial splits, whose leaves hold clipped references) or the count differs.
void refit(Bvh& bvh, std::span<const Aabb> prim_boxes);

// Same, reading the moved triangles (same index buffer, new positions).
void refit(Bvh& bvh, const TriangleMesh& mesh);

namespace detail {
// Whether refit can cut `bvh` into subtrees whose descendants are contiguous ranges and refit them in
// parallel (every builder's layout; otherwise one serial sweep).
bool refits_in_parallel(const Bvh& bvh);
}  // namespace detail

}  // namespace glint::accel
