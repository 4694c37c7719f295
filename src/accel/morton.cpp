#include "accel/morton.h"

#include "accel/radix_sort.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace glint::accel {
namespace {

struct CentroidBounds {
  Aabb box;
  bool finite = true;
};

// Maps centroids into [0, 1]^3 of their bounds; a flat (or subnormal) axis maps to 0.
struct UnitMapping {
  vec3 origin;
  vec3 scale;

  vec3 operator()(const vec3& p) const { return (p - origin) * scale; }
};

UnitMapping unit_mapping(std::span<const vec3> centroids) {
  const CentroidBounds bounds = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, centroids.size(), 8192), CentroidBounds{},
      [&](const tbb::blocked_range<size_t>& r, CentroidBounds acc) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
          acc.finite = acc.finite && is_finite(centroids[i]);
          acc.box.extend(centroids[i]);
        }
        return acc;
      },
      [](CentroidBounds a, const CentroidBounds& b) {
        a.box.extend(b.box);
        a.finite = a.finite && b.finite;
        return a;
      });
  if (!bounds.finite) fail("accel: Morton codes: a primitive centroid is not finite");
  return UnitMapping{bounds.box.min, unit_cube_scale(bounds.box.extent())};
}

// The top 30 bits of a 63-bit code: 21 bits per axis quantise floor(c * 2^21), whose top 10 bits
// are floor(c * 2^10), the 30-bit code's cells (cap included), so this is morton30 of the same point
// (tests check it).
constexpr uint32_t kCoarseShift = 33;

// Codes of every centroid with 63 bits, and prims = 0, 1, 2, ... in parallel.
MortonOrder fine_codes(std::span<const vec3> centroids, const UnitMapping& mapping) {
  MortonOrder order;
  order.codes = detail::ParallelArray<uint64_t>(centroids.size(), detail::kForOverwrite);
  order.prims.resize(centroids.size());  // written below, not zeroed (unzeroed_vector.h)
  tbb::parallel_for(tbb::blocked_range<size_t>(0, centroids.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      order.codes[i] = morton63(mapping(centroids[i]));
      order.prims[i] = static_cast<uint32_t>(i);
    }
  });
  return order;
}

// Sorted neighbours whose 30-bit codes are equal but whose 63-bit codes differ: the pairs 63 bits
// would put in order and 30 bits leave in index order (see kMaxMorton30CollisionFraction). Pairs
// with equal 63-bit codes (identical centroids among them) gain nothing from 63 bits and do not
// count. Codes alone, so no centroid is gathered.
size_t count_coarse_collisions(const MortonOrder& order) {
  if (order.codes.size() < 2) return 0;
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(1, order.codes.size(), 8192), size_t{0},
      [&](const tbb::blocked_range<size_t>& r, size_t acc) {
        for (size_t i = r.begin(); i != r.end(); ++i) {
          const uint64_t a = order.codes[i - 1], b = order.codes[i];
          acc += a >> kCoarseShift == b >> kCoarseShift && a != b;
        }
        return acc;
      },
      std::plus<>());
}

// Runs of this many pairs or fewer are finished by insertion sort, longer ones by a radix sort of
// their own.
constexpr size_t kInsertionSortRun = 64;

// Orders one run of equal 30-bit codes by the remaining 33 bits, stably (the run is in index order).
void sort_run(std::span<uint64_t> codes, std::span<uint32_t> prims) {
  if (codes.size() > kInsertionSortRun) {
    radix_sort_pairs_by_bits(codes, prims, 0, kCoarseShift);
    return;
  }
  for (size_t i = 1; i < codes.size(); ++i)
    for (size_t j = i; j > 0 && codes[j - 1] > codes[j]; --j) {
      std::swap(codes[j - 1], codes[j]);
      std::swap(prims[j - 1], prims[j]);
    }
}

// After the sort by the top 30 bits, sorts every run of equal top bits by the low 33: the result is
// the stable sort by all 63 bits, for the price of the runs alone. Runs are found by the chunk they
// start in, so each is sorted once, by one task, even where it crosses into the next chunk.
void sort_coarse_runs(MortonOrder& order) {
  const size_t count = order.codes.size();
  const std::span<uint64_t> codes(order.codes);
  const std::span<uint32_t> prims(order.prims);
  const auto coarse = [&](size_t i) { return codes[i] >> kCoarseShift; };
  tbb::parallel_for(tbb::blocked_range<size_t>(0, count, 8192), [&](const tbb::blocked_range<size_t>& r) {
    size_t begin = r.begin();
    while (begin != r.end() && begin > 0 && coarse(begin) == coarse(begin - 1)) ++begin;  // a run from before
    while (begin < r.end()) {
      size_t end = begin + 1;
      while (end < count && coarse(end) == coarse(begin)) ++end;
      if (end - begin > 1) sort_run(codes.subspan(begin, end - begin), prims.subspan(begin, end - begin));
      begin = end;
    }
  });
}

}  // namespace

MortonOrder sort_by_morton(std::span<const vec3> centroids) {
  // Both code lengths from one set of 63-bit codes: sorted by their top 30 bits first (which is the
  // 30-bit order), then, only where too many of those collide, every run of equal top bits by the
  // rest. A separate 30-bit sort followed by a full 63-bit one cost twice the codes and 12 passes.
  MortonOrder order = fine_codes(centroids, unit_mapping(centroids));
  radix_sort_pairs_by_bits(order.codes, order.prims, kCoarseShift, 64);
  const size_t collisions = count_coarse_collisions(order);
  if (static_cast<double>(collisions) <= kMaxMorton30CollisionFraction * static_cast<double>(centroids.size())) {
    order.bits = 30;
    tbb::parallel_for(tbb::blocked_range<size_t>(0, order.codes.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t i = r.begin(); i != r.end(); ++i) order.codes[i] >>= kCoarseShift;
    });
    return order;
  }
  order.bits = 63;
  sort_coarse_runs(order);
  return order;
}

}  // namespace glint::accel
