#pragma once
// Batch tracing on the CPU: one TBB-parallel loop of the single-ray kernels in traverse.h.
#include "accel/bvh.h"
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

#include <cstdint>
#include <span>

namespace glint::accel {

// hits[i] = closest hit of rays[i] (Hit{} on a miss; instance 0 on a hit). glint::Error when the
// spans differ in size, the BVH was built over a different number of triangles, or it is deeper
// than traversal supports.
void trace_closest(const Bvh& bvh, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<Hit> hits);

// occluded[i] = 1 when anything lies on rays[i] within [t_min, t_max], else 0 (shadow rays).
void trace_any(const Bvh& bvh, const TriangleMesh& mesh, std::span<const Ray> rays, std::span<uint8_t> occluded);

// Shared checks for batch entry points (also used by the two-level tracer).
void check_traceable(const Bvh& bvh, size_t prim_count, const char* what);
void check_batch_sizes(size_t ray_count, size_t result_count);

}  // namespace glint::accel
