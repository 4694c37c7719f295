#include "accel/morton.h"

#include "accel/radix_sort.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <numeric>

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

template <typename Encode>
MortonOrder sorted_codes(std::span<const vec3> centroids, const UnitMapping& mapping, uint32_t bits, Encode encode) {
  MortonOrder order;
  order.bits = bits;
  order.codes = detail::ParallelArray<uint64_t>(centroids.size(), detail::kForOverwrite);
  order.prims = detail::ParallelArray<uint32_t>(centroids.size(), detail::kForOverwrite);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, centroids.size(), 8192), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) {
      order.codes[i] = encode(mapping(centroids[i]));
      order.prims[i] = static_cast<uint32_t>(i);
    }
  });
  radix_sort_pairs(order.codes, order.prims, bits);
  return order;
}

// Sorted neighbours with the same code but different centroids (see kMaxMorton30CollisionFraction).
size_t count_collisions(const MortonOrder& order, std::span<const vec3> centroids) {
  if (order.codes.size() < 2) return 0;
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(1, order.codes.size(), 8192), size_t{0},
      [&](const tbb::blocked_range<size_t>& r, size_t acc) {
        for (size_t i = r.begin(); i != r.end(); ++i)
          if (order.codes[i] == order.codes[i - 1] && centroids[order.prims[i]] != centroids[order.prims[i - 1]])
            ++acc;
        return acc;
      },
      std::plus<>());
}

}  // namespace

MortonOrder sort_by_morton(std::span<const vec3> centroids) {
  const UnitMapping mapping = unit_mapping(centroids);
  MortonOrder order = sorted_codes(centroids, mapping, 30, [](const vec3& p) { return uint64_t{morton30(p)}; });
  const size_t collisions = count_collisions(order, centroids);
  if (static_cast<double>(collisions) <= kMaxMorton30CollisionFraction * static_cast<double>(centroids.size()))
    return order;
  return sorted_codes(centroids, mapping, 63, [](const vec3& p) { return morton63(p); });
}

}  // namespace glint::accel
