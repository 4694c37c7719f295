#pragma once
// Deterministic, tileable 2D noise for the procedural textures. Everything is a pure function of
// its arguments (integer hashing, no global random state), so a texture is identical on every run
// and platform, and every lattice wraps at `period` so textures tile without seams.
#include <cstdint>

namespace glint::procedural {

// A well-mixed 32-bit hash of a lattice point and a seed.
std::uint32_t hash_lattice(int x, int y, std::uint32_t seed);

// Uniform in [0, 1) from a hash, for per-tile/per-brick colour variation.
float hash_to_unit(std::uint32_t h);

// Value noise in [0, 1] on the unit lattice, C1-smooth (quintic fade), wrapping every `period`
// lattice cells in x and y.
float value_noise(float x, float y, int period, std::uint32_t seed);

// Fractal sum of `octaves` value-noise layers (frequency doubles, amplitude halves), normalised to
// [0, 1]. Tileable over [0, period) when x, y are in lattice units of the first octave.
float fbm(float x, float y, int period, int octaves, std::uint32_t seed);

}  // namespace glint::procedural
