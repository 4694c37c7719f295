#pragma once
// Internal: the compiled instances of the wide traversal kernel, one set per instruction set
// (wide_bvh_kernels_sse.cpp, wide_bvh_kernels_avx2.cpp). Each traces a contiguous range of rays
// on the calling thread; wide_bvh_trace.cpp picks one and spreads ranges over TBB. The AVX2 ones
// may only be called when the CPU has AVX2.
#include "accel/ray.h"
#include "accel/wide/wide_bvh.h"

#include <cstddef>
#include <cstdint>

namespace glint::accel::wide_kernel {

void closest_sse4(const WideBvh<4>& bvh, const Ray* rays, Hit* hits, size_t count);
void any_sse4(const WideBvh<4>& bvh, const Ray* rays, uint8_t* occluded, size_t count);
void closest_sse8(const WideBvh<8>& bvh, const Ray* rays, Hit* hits, size_t count);
void any_sse8(const WideBvh<8>& bvh, const Ray* rays, uint8_t* occluded, size_t count);
void closest_avx8(const WideBvh<8>& bvh, const Ray* rays, Hit* hits, size_t count);
void any_avx8(const WideBvh<8>& bvh, const Ray* rays, uint8_t* occluded, size_t count);

}  // namespace glint::accel::wide_kernel
