#pragma once
// Batch tracing through a kd-tree on the CPU: one TBB-parallel loop of the single-ray kernels in
// kdtree_traverse.h, with the same contract as trace.h's BVH batches.
#include "accel/kdtree/kdtree.h"
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

#include <cstdint>
#include <span>

namespace glint::accel {

// hits[i] = closest hit of rays[i] (Hit{} on a miss; instance 0 on a hit). glint::Error when the
// spans differ in size, the tree was built over a different number of triangles, or it is deeper
// than traversal supports.
void trace_closest(const KdTree& tree, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<Hit> hits);

// occluded[i] = 1 when anything lies on rays[i] within [t_min, t_max], else 0.
void trace_any(const KdTree& tree, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<uint8_t> occluded);

}  // namespace glint::accel
