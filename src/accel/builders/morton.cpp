#include "accel/builders/morton.h"

#include "accel/builders/radix_sort.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <numeric>
#include <tuple>
#include <utility>
#include <vector>

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

// Every 7-bit value with two zero bits after each of its bits (spread_bits_21 of values below 128).
struct SpreadBy3Table {
  std::array<uint64_t, 128> entries{};
  constexpr SpreadBy3Table() {
    for (uint32_t v = 0; v < 128; ++v)
      for (uint32_t bit = 0; bit < 7; ++bit) entries[v] |= uint64_t{(v >> bit) & 1u} << (3 * bit);
  }
};
constexpr SpreadBy3Table kSpreadBy3;

uint64_t spread_bits_21_by_table(uint32_t v) {
  const auto& t = kSpreadBy3.entries;
  return t[v & 127u] | t[(v >> 7) & 127u] << 21 | t[(v >> 14) & 127u] << 42;
}

// Codes of every centroid with 63 bits, and prims = 0, 1, 2, ... in parallel.
MortonOrder fine_codes(std::span<const vec3> centroids, const UnitMapping& mapping) {
  MortonOrder order;
  order.codes = detail::ParallelArray<uint64_t>(centroids.size(), detail::kForOverwrite);
  order.prims.resize(centroids.size());  // written below, not zeroed (unzeroed_vector.h)
  tbb::parallel_for(tbb::blocked_range<size_t>(0, centroids.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      order.codes[i] = detail::morton63_by_table(mapping(centroids[i]));
      order.prims[i] = static_cast<uint32_t>(i);
    }
  });
  return order;
}

// Runs of this many pairs or fewer are sorted by insertion sort, longer ones by a radix sort (or,
// by primitive, std::sort) of their own.
constexpr size_t kInsertionSortRun = 64;

// Orders one run of equal 30-bit codes by the remaining 33 bits, stably (the run is in index order).
void sort_run_by_fine_bits(std::span<uint64_t> codes, std::span<uint32_t> prims) {
  if (codes.size() > kInsertionSortRun)
    radix_sort_pairs_by_bits(codes, prims, 0, kCoarseShift);
  else
    insertion_sort_pairs(codes, prims, [](uint64_t code, uint32_t) { return code; });
}

// Puts one run of equal 30-bit codes back in index order, the 30-bit stable order.
void sort_run_by_prim(std::span<uint64_t> codes, std::span<uint32_t> prims) {
  if (codes.size() <= kInsertionSortRun) {
    insertion_sort_pairs(codes, prims, [](uint64_t, uint32_t prim) { return prim; });
    return;
  }
  std::vector<std::pair<uint32_t, uint64_t>> pairs(codes.size());
  for (size_t i = 0; i < codes.size(); ++i) pairs[i] = {prims[i], codes[i]};
  std::sort(pairs.begin(), pairs.end());
  for (size_t i = 0; i < codes.size(); ++i) std::tie(prims[i], codes[i]) = pairs[i];
}

// For a range of the arrays sorted by the top 30 bits that holds whole runs of equal top bits:
// counts the neighbours whose 30-bit codes are equal but whose 63-bit codes differ (the pairs 63 bits
// would put in order and 30 bits leave in index order, see kMaxMorton30CollisionFraction; pairs with
// equal 63-bit codes, identical centroids among them, gain nothing from 63 bits and do not count),
// then sorts every run by the low 33 bits. Done range by range as the sort finishes them, in cache;
// sort_by_morton undoes it where 30 bits win.
size_t count_and_refine_runs(std::span<uint64_t> codes, std::span<uint32_t> prims) {
  size_t collisions = 0;
  size_t begin = 0;
  while (begin < codes.size()) {
    size_t end = begin + 1;
    while (end < codes.size() && codes[end] >> kCoarseShift == codes[begin] >> kCoarseShift) {
      collisions += codes[end] != codes[end - 1];
      ++end;
    }
    if (end - begin > 1) sort_run_by_fine_bits(codes.subspan(begin, end - begin), prims.subspan(begin, end - begin));
    begin = end;
  }
  return collisions;
}

// Puts every run of equal top 30 bits back in index order (sort_run_by_prim), in parallel. Runs are
// found by the chunk they start in, so each is sorted once, by one task, even where it crosses into
// the next chunk.
void restore_coarse_runs(MortonOrder& order) {
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
      if (end - begin > 1) sort_run_by_prim(codes.subspan(begin, end - begin), prims.subspan(begin, end - begin));
      begin = end;
    }
  });
}

}  // namespace

uint64_t detail::morton63_by_table(const vec3& unit) {
  constexpr uint32_t cells = 1u << 21;
  return spread_bits_21_by_table(detail::quantise_unit(unit.x, cells)) |
         spread_bits_21_by_table(detail::quantise_unit(unit.y, cells)) << 1 |
         spread_bits_21_by_table(detail::quantise_unit(unit.z, cells)) << 2;
}

MortonOrder sort_by_morton(std::span<const vec3> centroids) {
  // Both code lengths from one set of 63-bit codes, sorted by their top 30 bits (which are the
  // 30-bit codes) with every run of equal top bits then sorted by the rest as soon as its part of
  // the sort is done, in cache: the stable 63-bit order. Where few enough neighbours collide, 30
  // bits win and the runs go back to index order. A separate 30-bit sort followed by a full 63-bit
  // one cost twice the codes and 12 passes over memory; refining the runs in a pass of their own
  // cost another pass, and counting the collisions one more.
  MortonOrder order = fine_codes(centroids, unit_mapping(centroids));
  std::atomic<size_t> collisions{0};
  const std::span<uint64_t> codes(order.codes);
  const std::span<uint32_t> prims(order.prims);
  // Bits [33, 63): bit 63 of a 63-bit code is 0, and the sort's first pass should split on bits that vary.
  radix_sort_pairs_by_bits(codes, prims, kCoarseShift, 63, [&](size_t begin, size_t end) {
    collisions.fetch_add(count_and_refine_runs(codes.subspan(begin, end - begin), prims.subspan(begin, end - begin)),
                         std::memory_order_relaxed);
  });
  if (static_cast<double>(collisions.load()) > kMaxMorton30CollisionFraction * static_cast<double>(centroids.size())) {
    order.bits = 63;
    return order;
  }
  order.bits = 30;
  restore_coarse_runs(order);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, order.codes.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) order.codes[i] >>= kCoarseShift;
  });
  return order;
}

}  // namespace glint::accel
