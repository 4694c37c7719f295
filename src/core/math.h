#pragma once
// Shared math: glm for vectors and matrices, an axis-aligned box, and the GLINT_HOST_DEVICE macro
// that marks functions usable from both host and CUDA device code (pbrt-v4 style).
#include <glm/glm.hpp>

#include <cmath>
#include <limits>

#if defined(__CUDACC__)
#define GLINT_HOST_DEVICE __host__ __device__
#else
#define GLINT_HOST_DEVICE
#endif

namespace glint {

using glm::mat4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

// Axis-aligned bounding box; default-constructed it is empty (min > max) and grows with extend().
struct Aabb {
  vec3 min{std::numeric_limits<float>::infinity()};
  vec3 max{-std::numeric_limits<float>::infinity()};

  GLINT_HOST_DEVICE bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  GLINT_HOST_DEVICE void extend(const vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  GLINT_HOST_DEVICE void extend(const Aabb& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  GLINT_HOST_DEVICE vec3 extent() const { return empty() ? vec3(0.0f) : max - min; }
  // Per axis, the largest absolute coordinate in the box: how far from the origin it reaches, which
  // sets the float step of its coordinates (ray offsets, precision checks, conservative slack).
  GLINT_HOST_DEVICE vec3 largest_abs() const { return glm::max(glm::abs(min), glm::abs(max)); }
  GLINT_HOST_DEVICE float largest_abs_coordinate() const {
    const vec3 a = largest_abs();
    return glm::max(a.x, glm::max(a.y, a.z));
  }
  GLINT_HOST_DEVICE vec3 center() const { return 0.5f * (min + max); }
  GLINT_HOST_DEVICE bool contains(const vec3& p) const {
    return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
  }
};

// The box of `box` after an affine transform (the 8 corners transformed, then bounded).
Aabb transform_aabb(const mat4& transform, const Aabb& box);

inline bool is_finite(const vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
inline bool is_finite(const mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

}  // namespace glint
