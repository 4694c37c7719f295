#pragma once
// Morton (Z-order) codes of one point in the unit cube, usable from host and CUDA device code, so
// the CPU builders (accel/builders/morton.cpp) and the GPU builders (cuda/gpu_morton.cu) quantise and
// interleave exactly alike: each axis quantised to floor(c * cells) capped at cells - 1 (values
// outside [0, 1] take the nearest cell), bits interleaved with x in the lowest of every three.
#include "core/math.h"

#include <cstdint>
#include <limits>

namespace glint::accel {
namespace detail {

// Spreads the low 10 bits of v so that two zero bits follow each: b9..b0 -> b9 0 0 b8 0 0 ... b0.
GLINT_HOST_DEVICE inline uint32_t spread_bits_10(uint32_t v) {
  v &= 0x3ffu;
  v = (v | (v << 16)) & 0x030000ffu;
  v = (v | (v << 8)) & 0x0300f00fu;
  v = (v | (v << 4)) & 0x030c30c3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// The same for the low 21 bits into a 64-bit word.
GLINT_HOST_DEVICE inline uint64_t spread_bits_21(uint64_t v) {
  v &= 0x1fffffull;
  v = (v | (v << 32)) & 0x001f00000000ffffull;
  v = (v | (v << 16)) & 0x001f0000ff0000ffull;
  v = (v | (v << 8)) & 0x100f00f00f00f00full;
  v = (v | (v << 4)) & 0x10c30c30c30c30c3ull;
  v = (v | (v << 2)) & 0x1249249249249249ull;
  return v;
}

GLINT_HOST_DEVICE inline uint32_t quantise_unit(float unit, uint32_t cells) {
  // Clamped in float before converting (converting an out-of-range float is undefined); NaN -> 0.
  const float scaled = unit * static_cast<float>(cells);
  if (!(scaled > 0.0f)) return 0;
  return scaled < static_cast<float>(cells - 1) ? static_cast<uint32_t>(scaled) : cells - 1;
}

}  // namespace detail

// 10 bits per axis: a 30-bit code.
GLINT_HOST_DEVICE inline uint32_t morton30(const vec3& unit) {
  constexpr uint32_t cells = 1u << 10;
  return detail::spread_bits_10(detail::quantise_unit(unit.x, cells)) |
         (detail::spread_bits_10(detail::quantise_unit(unit.y, cells)) << 1) |
         (detail::spread_bits_10(detail::quantise_unit(unit.z, cells)) << 2);
}

// 21 bits per axis: a 63-bit code.
GLINT_HOST_DEVICE inline uint64_t morton63(const vec3& unit) {
  constexpr uint32_t cells = 1u << 21;
  return detail::spread_bits_21(detail::quantise_unit(unit.x, cells)) |
         (detail::spread_bits_21(detail::quantise_unit(unit.y, cells)) << 1) |
         (detail::spread_bits_21(detail::quantise_unit(unit.z, cells)) << 2);
}

// The scale that maps a box of this extent onto the unit cube, per axis: 1 / extent, or 0 for a
// flat (or subnormal) axis, whose points then all map to 0.
GLINT_HOST_DEVICE inline vec3 unit_cube_scale(const vec3& extent) {
  vec3 scale(0.0f);
  for (int axis = 0; axis < 3; ++axis) {
    if (!(extent[axis] > 0.0f)) continue;
    const float inverse = 1.0f / extent[axis];
    if (inverse <= std::numeric_limits<float>::max()) scale[axis] = inverse;  // not infinite
  }
  return scale;
}

}  // namespace glint::accel
