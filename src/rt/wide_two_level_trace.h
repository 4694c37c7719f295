#pragma once
// The cpu backend's two-level batch over 8-wide BLASes. The TLAS (a binary BVH over instances, small)
// is walked with accel's scalar traversal; at an instance leaf the ray moves into the instance's
// object space exactly as accel/tlas_traverse.h does, and the BLAS's 8-wide BVH (accel's SSE/AVX2
// kernel) finds its closest hit below the current closest t. A BLAS without a wide BVH (its builder's
// BVH cannot be collapsed: sbvh's split references) is walked by the binary traversal instead, so one
// scene may mix both. Hits follow accel::trace_closest(const Tlas&, ...): instance = index in
// tlas.instances, prim = triangle index in that instance's mesh, t along the world ray.
#include "accel/ray.h"
#include "accel/tlas.h"
#include "accel/wide/wide_bvh.h"

#include <cstdint>
#include <span>

namespace glint::rt {

// wide[b] is the 8-wide BVH collapsed from blases[b]'s BVH, or nullptr to trace blases[b] itself.
// TBB-parallel over rays. glint::Error when the spans differ in size, an instance names a BLAS past
// the end, or a wide BVH does not match its BLAS (triangle count) or is too deep to traverse.
void trace_closest_wide(const accel::Tlas& tlas, std::span<const accel::Blas> blases,
                        std::span<const accel::WideBvh8* const> wide, std::span<const accel::Ray> rays,
                        std::span<accel::Hit> hits);

// The occlusion query over the same structures: occluded[i] = 1 when rays[i] hits any triangle within
// [t_min, t_max], else 0. The same TLAS walk in any-hit mode (accel::traverse_bvh<true>): each
// instance's BLAS is entered with the 8-wide any-hit kernel (or the binary any-hit traversal) and the
// walk ends at the first hit. Same errors as trace_closest_wide.
void trace_any_wide(const accel::Tlas& tlas, std::span<const accel::Blas> blases,
                    std::span<const accel::WideBvh8* const> wide, std::span<const accel::Ray> rays,
                    std::span<uint8_t> occluded);

}  // namespace glint::rt
