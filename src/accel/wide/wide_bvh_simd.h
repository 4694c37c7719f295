#pragma once
// Internal: the few SIMD float operations the wide traversal kernel needs, behind one interface so
// that a single kernel (wide_bvh_kernel.h) serves three instruction sets:
//   SimdSse4  4 lanes, SSE2 (every x86-64 CPU)         for WideBvh<4>
//   SimdSse8  8 lanes as two SSE2 halves               for WideBvh<8> on CPUs without AVX2
//   SimdAvx8  8 lanes, AVX2                            for WideBvh<8>
// Comparisons are ordered (false when either side is NaN) like the scalar C++ comparisons of the
// binary traversal, and min/max return their second operand when either is NaN, which is what
// the scalar slab test's `a > b ? a : b` does. No FMA: products and sums round exactly like the
// scalar watertight test, so the wide kernels find bit-identical t, u, v.
#include <immintrin.h>

#define GLINT_SIMD_INLINE inline __attribute__((always_inline))
#define GLINT_AVX2_INLINE inline __attribute__((always_inline, target("avx2")))

namespace glint::accel::simd {

struct SimdSse4 {
  static constexpr int kWidth = 4;
  using F = __m128;
  static GLINT_SIMD_INLINE F load(const float* p) { return _mm_load_ps(p); }
  static GLINT_SIMD_INLINE void store(float* p, F a) { _mm_store_ps(p, a); }
  static GLINT_SIMD_INLINE F set1(float x) { return _mm_set1_ps(x); }
  static GLINT_SIMD_INLINE F add(F a, F b) { return _mm_add_ps(a, b); }
  static GLINT_SIMD_INLINE F sub(F a, F b) { return _mm_sub_ps(a, b); }
  static GLINT_SIMD_INLINE F mul(F a, F b) { return _mm_mul_ps(a, b); }
  static GLINT_SIMD_INLINE F div(F a, F b) { return _mm_div_ps(a, b); }
  static GLINT_SIMD_INLINE F min(F a, F b) { return _mm_min_ps(a, b); }
  static GLINT_SIMD_INLINE F max(F a, F b) { return _mm_max_ps(a, b); }
  static GLINT_SIMD_INLINE F lt(F a, F b) { return _mm_cmplt_ps(a, b); }
  static GLINT_SIMD_INLINE F le(F a, F b) { return _mm_cmple_ps(a, b); }
  static GLINT_SIMD_INLINE F gt(F a, F b) { return _mm_cmpgt_ps(a, b); }
  static GLINT_SIMD_INLINE F ge(F a, F b) { return _mm_cmpge_ps(a, b); }
  static GLINT_SIMD_INLINE F eq(F a, F b) { return _mm_cmpeq_ps(a, b); }
  static GLINT_SIMD_INLINE F bit_or(F a, F b) { return _mm_or_ps(a, b); }
  static GLINT_SIMD_INLINE F bit_and(F a, F b) { return _mm_and_ps(a, b); }
  static GLINT_SIMD_INLINE unsigned mask(F a) { return static_cast<unsigned>(_mm_movemask_ps(a)); }
};

struct SimdSse8 {
  static constexpr int kWidth = 8;
  struct F {
    __m128 lo, hi;
  };
  static GLINT_SIMD_INLINE F load(const float* p) { return {_mm_load_ps(p), _mm_load_ps(p + 4)}; }
  static GLINT_SIMD_INLINE void store(float* p, F a) {
    _mm_store_ps(p, a.lo);
    _mm_store_ps(p + 4, a.hi);
  }
  static GLINT_SIMD_INLINE F set1(float x) { return {_mm_set1_ps(x), _mm_set1_ps(x)}; }
  static GLINT_SIMD_INLINE F add(F a, F b) { return {_mm_add_ps(a.lo, b.lo), _mm_add_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F sub(F a, F b) { return {_mm_sub_ps(a.lo, b.lo), _mm_sub_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F mul(F a, F b) { return {_mm_mul_ps(a.lo, b.lo), _mm_mul_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F div(F a, F b) { return {_mm_div_ps(a.lo, b.lo), _mm_div_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F min(F a, F b) { return {_mm_min_ps(a.lo, b.lo), _mm_min_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F max(F a, F b) { return {_mm_max_ps(a.lo, b.lo), _mm_max_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F lt(F a, F b) { return {_mm_cmplt_ps(a.lo, b.lo), _mm_cmplt_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F le(F a, F b) { return {_mm_cmple_ps(a.lo, b.lo), _mm_cmple_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F gt(F a, F b) { return {_mm_cmpgt_ps(a.lo, b.lo), _mm_cmpgt_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F ge(F a, F b) { return {_mm_cmpge_ps(a.lo, b.lo), _mm_cmpge_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F eq(F a, F b) { return {_mm_cmpeq_ps(a.lo, b.lo), _mm_cmpeq_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F bit_or(F a, F b) { return {_mm_or_ps(a.lo, b.lo), _mm_or_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE F bit_and(F a, F b) { return {_mm_and_ps(a.lo, b.lo), _mm_and_ps(a.hi, b.hi)}; }
  static GLINT_SIMD_INLINE unsigned mask(F a) {
    return static_cast<unsigned>(_mm_movemask_ps(a.lo) | (_mm_movemask_ps(a.hi) << 4));
  }
};

// Every member carries target("avx2"): it may only be inlined into functions that have it too
// (the AVX2 translation unit's kernel instances), and only called after a CPU check.
struct SimdAvx8 {
  static constexpr int kWidth = 8;
  using F = __m256;
  static GLINT_AVX2_INLINE F load(const float* p) { return _mm256_load_ps(p); }
  static GLINT_AVX2_INLINE void store(float* p, F a) { _mm256_store_ps(p, a); }
  static GLINT_AVX2_INLINE F set1(float x) { return _mm256_set1_ps(x); }
  static GLINT_AVX2_INLINE F add(F a, F b) { return _mm256_add_ps(a, b); }
  static GLINT_AVX2_INLINE F sub(F a, F b) { return _mm256_sub_ps(a, b); }
  static GLINT_AVX2_INLINE F mul(F a, F b) { return _mm256_mul_ps(a, b); }
  static GLINT_AVX2_INLINE F div(F a, F b) { return _mm256_div_ps(a, b); }
  static GLINT_AVX2_INLINE F min(F a, F b) { return _mm256_min_ps(a, b); }
  static GLINT_AVX2_INLINE F max(F a, F b) { return _mm256_max_ps(a, b); }
  static GLINT_AVX2_INLINE F lt(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LT_OQ); }
  static GLINT_AVX2_INLINE F le(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_LE_OQ); }
  static GLINT_AVX2_INLINE F gt(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_GT_OQ); }
  static GLINT_AVX2_INLINE F ge(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_GE_OQ); }
  static GLINT_AVX2_INLINE F eq(F a, F b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
  static GLINT_AVX2_INLINE F bit_or(F a, F b) { return _mm256_or_ps(a, b); }
  static GLINT_AVX2_INLINE F bit_and(F a, F b) { return _mm256_and_ps(a, b); }
  static GLINT_AVX2_INLINE unsigned mask(F a) { return static_cast<unsigned>(_mm256_movemask_ps(a)); }
};

}  // namespace glint::accel::simd
