#pragma once
// Batch tracing of a two-level structure on the CPU (TBB-parallel over rays).
#include "accel/ray.h"
#include "accel/tlas.h"

#include <cstdint>
#include <span>

namespace glint::accel {

// `blases` must be the array the TLAS was built with (same indices). Hit.instance is the index in
// tlas.instances, Hit.prim the triangle index in that instance's mesh.
void trace_closest(const Tlas& tlas, std::span<const Blas> blases, std::span<const Ray> rays, std::span<Hit> hits);
void trace_any(const Tlas& tlas, std::span<const Blas> blases, std::span<const Ray> rays, std::span<uint8_t> occluded);

}  // namespace glint::accel
