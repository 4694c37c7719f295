#pragma once
// Rays and hit records: plain, trivially copyable data shared by CPU and (later) CUDA traversal.
#include "core/math.h"

#include <cstdint>
#include <limits>
#include <type_traits>

namespace glint::accel {

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// A ray segment origin + t * direction for t in [t_min, t_max]. The direction need not be
// normalised: t is measured in units of `direction`, which keeps t unchanged when the ray is moved
// into an instance's object space by an affine transform. Laid out as two 16-byte halves for
// coalesced loads on the GPU.
struct Ray {
  vec3 origin{0.0f};
  float t_min = 0.0f;
  vec3 direction{0.0f, 0.0f, 1.0f};
  float t_max = kInfinity;
};

// The result of a closest-hit query. A miss has prim == kInvalidIndex (and t == infinity).
// For a hit, the point is (1 - u - v) * v0 + u * v1 + v * v2 of triangle `prim` (its index in the
// mesh given to the builder, not its position in the BVH), of instance `instance` (0 for a
// single-level BVH).
struct Hit {
  static constexpr uint32_t kInvalidIndex = 0xFFFFFFFFu;

  float t = kInfinity;
  uint32_t instance = kInvalidIndex;
  uint32_t prim = kInvalidIndex;
  float u = 0.0f;
  float v = 0.0f;

  GLINT_HOST_DEVICE bool valid() const { return prim != kInvalidIndex; }
};

static_assert(std::is_trivially_copyable_v<Ray> && sizeof(Ray) == 32);
static_assert(std::is_trivially_copyable_v<Hit> && sizeof(Hit) == 20);

}  // namespace glint::accel
