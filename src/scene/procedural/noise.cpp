#include "scene/procedural/noise.h"

#include <cmath>

namespace glint::procedural {

std::uint32_t hash_lattice(int x, int y, std::uint32_t seed) {
  // Multiply-xorshift mixing of the three words; the constants are odd numbers with good bit
  // dispersion, and each round spreads high bits back down.
  std::uint32_t h = seed * 0x9E3779B1u;
  h ^= static_cast<std::uint32_t>(x) * 0x85EBCA77u;
  h = (h ^ (h >> 15)) * 0x2C1B3C6Du;
  h ^= static_cast<std::uint32_t>(y) * 0xC2B2AE3Du;
  h = (h ^ (h >> 13)) * 0x297A2D39u;
  return h ^ (h >> 16);
}

float hash_to_unit(std::uint32_t h) { return static_cast<float>(h >> 8) * (1.0f / 16777216.0f); }

namespace {
int wrap(int i, int period) {
  const int r = i % period;
  return r < 0 ? r + period : r;
}
float fade(float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); }
}  // namespace

float value_noise(float x, float y, int period, std::uint32_t seed) {
  const float fx = std::floor(x), fy = std::floor(y);
  const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
  const float tx = fade(x - fx), ty = fade(y - fy);
  const int x0 = wrap(ix, period), x1 = wrap(ix + 1, period);
  const int y0 = wrap(iy, period), y1 = wrap(iy + 1, period);
  const float a = hash_to_unit(hash_lattice(x0, y0, seed)), b = hash_to_unit(hash_lattice(x1, y0, seed));
  const float c = hash_to_unit(hash_lattice(x0, y1, seed)), d = hash_to_unit(hash_lattice(x1, y1, seed));
  const float top = a + (b - a) * tx, bottom = c + (d - c) * tx;
  return top + (bottom - top) * ty;
}

float fbm(float x, float y, int period, int octaves, std::uint32_t seed) {
  float sum = 0.0f, amplitude = 1.0f, total = 0.0f, frequency = 1.0f;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * value_noise(x * frequency, y * frequency, period << o, seed + static_cast<std::uint32_t>(o) * 131u);
    total += amplitude;
    amplitude *= 0.5f;
    frequency *= 2.0f;
  }
  return sum / total;
}

}  // namespace glint::procedural
