#include "app/accel_bench/hit_check.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint::accel_bench {

std::optional<std::string> hit_disagreement(const accel::Hit& reference, const accel::Hit& actual) {
  if (reference.valid() != actual.valid())
    return reference.valid() ? fmt::format("missed, the reference hits triangle {} at t {}", reference.prim, reference.t)
                             : fmt::format("hit triangle {} at t {}, the reference misses", actual.prim, actual.t);
  if (!reference.valid()) return std::nullopt;
  // Relative to the larger t, with a floor so hits right at the origin compare by absolute error.
  const float scale = std::max({std::abs(reference.t), std::abs(actual.t), 1e-3f});
  if (std::abs(reference.t - actual.t) > kHitRelativeTolerance * scale)
    return fmt::format("hit triangle {} at t {}, the reference hits triangle {} at t {}", actual.prim, actual.t,
                       reference.prim, reference.t);
  return std::nullopt;
}

void check_hits(std::string_view structure, std::string_view reference, std::span<const accel::Ray> rays,
                std::span<const accel::Hit> reference_hits, std::span<const accel::Hit> hits) {
  if (rays.size() != reference_hits.size() || rays.size() != hits.size())
    fail("accel-bench: {} rays, {} hits of {}, {} hits of {}", rays.size(), reference_hits.size(), reference,
         hits.size(), structure);
  for (size_t i = 0; i < rays.size(); ++i) {
    if (const auto why = hit_disagreement(reference_hits[i], hits[i])) {
      const accel::Ray& ray = rays[i];
      fail("accel-bench: {} disagrees with {} on ray {} (origin ({}, {}, {}), direction ({}, {}, {})): {}", structure,
           reference, i, ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
           *why);
    }
  }
}

}  // namespace glint::accel_bench
