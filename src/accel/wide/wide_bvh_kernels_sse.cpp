// The SSE2 instances of the wide kernel: 4-wide, and 8-wide as two 4-lane halves (the fallback for
// CPUs without AVX2). SSE2 is part of x86-64, so no target attribute is needed.
#define GLINT_WIDE_KERNEL_ATTR
#include "accel/wide/wide_bvh_kernel.h"
#include "accel/wide/wide_bvh_kernels.h"

namespace glint::accel::wide_kernel {

void closest_sse4(const WideBvh<4>& bvh, const Ray* rays, Hit* hits, size_t count) {
  trace_closest_range<simd::SimdSse4, 4>(bvh, rays, hits, count);
}

void any_sse4(const WideBvh<4>& bvh, const Ray* rays, uint8_t* occluded, size_t count) {
  trace_any_range<simd::SimdSse4, 4>(bvh, rays, occluded, count);
}

void closest_sse8(const WideBvh<8>& bvh, const Ray* rays, Hit* hits, size_t count) {
  trace_closest_range<simd::SimdSse8, 8>(bvh, rays, hits, count);
}

void any_sse8(const WideBvh<8>& bvh, const Ray* rays, uint8_t* occluded, size_t count) {
  trace_any_range<simd::SimdSse8, 8>(bvh, rays, occluded, count);
}

}  // namespace glint::accel::wide_kernel
