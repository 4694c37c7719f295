// The AVX2 instance of the 8-wide kernel. Only the kernel functions are compiled for AVX2 (target
// attribute), not this whole file, so no AVX2 code can leak into inline functions other files
// share; the entry points below are plain functions that wide_bvh_trace.cpp calls only after
// __builtin_cpu_supports("avx2"). No "fma" in the target: fused multiply-adds would round
// differently from the scalar watertight test and break bit-identical hits.
#define GLINT_WIDE_KERNEL_ATTR __attribute__((target("avx2")))
#include "accel/wide/wide_bvh_kernel.h"
#include "accel/wide/wide_bvh_kernels.h"

namespace glint::accel::wide_kernel {

void closest_avx8(const WideBvh<8>& bvh, const Ray* rays, Hit* hits, size_t count) {
  trace_closest_range<simd::SimdAvx8, 8>(bvh, rays, hits, count);
}

void any_avx8(const WideBvh<8>& bvh, const Ray* rays, uint8_t* occluded, size_t count) {
  trace_any_range<simd::SimdAvx8, 8>(bvh, rays, occluded, count);
}

}  // namespace glint::accel::wide_kernel
