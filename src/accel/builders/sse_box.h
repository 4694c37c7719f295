#pragma once
// Internal to the top-down builders: a box as two SSE rows (lane 3 ignored), for the SAH sweeps and
// binning. Every operation gives bit for bit what Aabb and half_area() give, so code using it finds
// exactly the splits the scalar code found:
//  - glm::min(a, b) is (b < a ? b : a) and _mm_min_ps(x, y) is (x < y ? x : y), so Aabb::extend's
//    glm::min(min, other.min) is _mm_min_ps(other.min, min), signed zeros and NaNs included (and
//    likewise for max);
//  - half_area multiplies and adds the same lanes in the same order (no FMA contraction on x86-64
//    without -mfma), and is 0 for an empty box as Aabb::extent() makes it.
#include "core/math.h"

#include <xmmintrin.h>

#include <limits>

namespace glint::accel::detail {

struct SseBox {
  __m128 lo = _mm_set1_ps(std::numeric_limits<float>::infinity());
  __m128 hi = _mm_set1_ps(-std::numeric_limits<float>::infinity());

  static SseBox load(const float* lo4, const float* hi4) { return {_mm_loadu_ps(lo4), _mm_loadu_ps(hi4)}; }
  void extend(const SseBox& other) {
    lo = _mm_min_ps(other.lo, lo);
    hi = _mm_max_ps(other.hi, hi);
  }
  static SseBox of(const Aabb& box) {
    return {_mm_setr_ps(box.min.x, box.min.y, box.min.z, 0.0f), _mm_setr_ps(box.max.x, box.max.y, box.max.z, 0.0f)};
  }
  Aabb aabb() const {
    alignas(16) float l[4], h[4];
    _mm_store_ps(l, lo);
    _mm_store_ps(h, hi);
    return {vec3(l[0], l[1], l[2]), vec3(h[0], h[1], h[2])};
  }
  float half_area() const {
    if (_mm_movemask_ps(_mm_cmpgt_ps(lo, hi)) & 0b111) return 0.0f;  // empty on x, y or z
    const __m128 e = _mm_sub_ps(hi, lo);
    const __m128 products = _mm_mul_ps(e, _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1)));  // xy, yz, zx
    return (_mm_cvtss_f32(products) + _mm_cvtss_f32(_mm_shuffle_ps(products, products, 1))) +
           _mm_cvtss_f32(_mm_shuffle_ps(products, products, 2));
  }
};

}  // namespace glint::accel::detail
