#pragma once
// Morton (Z-order) codes of primitive centroids, the spatial order the bottom-up builders (lbvh,
// trbvh, ploc) start from: quantise each centroid in the centroid bounds, interleave the bits of
// x, y and z (x in the lowest of every three bits), sort the codes.
#include "accel/builders/build_options.h"
#include "accel/builders/morton_code.h"
#include "accel/builders/parallel_array.h"
#include "accel/unzeroed_vector.h"
#include "core/math.h"

#include <cstdint>
#include <span>

namespace glint::accel {

// morton30 (10 bits per axis) and morton63 (21 bits per axis) of a point in [0, 1]^3 are in
// accel/builders/morton_code.h, shared with the GPU builders.

// Centroids sorted along the Z curve. codes[i] is the code of primitive prims[i]; equal codes keep
// the primitives in index order (the radix sort is stable), so the result is deterministic. The
// arrays are filled by parallel loops from the start (parallel_array.h), not zeroed by one thread;
// prims is the container a Bvh keeps its prim_indices in, as lbvh's are exactly this order.
struct MortonOrder {
  detail::ParallelArray<uint64_t> codes;
  UnzeroedVector<uint32_t> prims;
  uint32_t bits = 0;  // 30 or 63
};

// When 30-bit codes are enough: at most this fraction of sorted neighbours may share a 30-bit code
// while their 63-bit codes differ. Beyond it (fine detail in a large scene: 1024 cells per axis are
// too coarse) the order inside those cells would be arbitrary, so 63 bits are used. Pairs that 63
// bits cannot separate either (identical centroids, among others) do not count.
inline constexpr double kMaxMorton30CollisionFraction = 0.01;

// Computes, checks and sorts the codes of `centroids` (in their bounding box; a flat axis maps to 0),
// in parallel. glint::Error when a centroid is not finite.
MortonOrder sort_by_morton(std::span<const vec3> centroids);

namespace detail {

// morton63 as sort_by_morton computes it on the CPU: the same bits (tests compare every bit), with
// each 21-bit coordinate spread by three lookups in a table of 128 entries instead of shifts and
// masks, which made computing the codes about half of it.
uint64_t morton63_by_table(const vec3& unit);

}  // namespace detail

}  // namespace glint::accel
