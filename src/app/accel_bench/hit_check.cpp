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

namespace {

float edge_distance(const accel::Hit& hit) { return std::min({hit.u, hit.v, 1.0f - hit.u - hit.v}); }

}  // namespace

bool is_edge_graze(const accel::Hit& reference, const accel::Hit& actual) {
  // The hit the other one missed is the nearer one (or the only one).
  const accel::Hit* missed = nullptr;
  if (reference.valid() && (!actual.valid() || reference.t < actual.t)) missed = &reference;
  if (actual.valid() && (!reference.valid() || actual.t < reference.t)) missed = &actual;
  return missed != nullptr && edge_distance(*missed) < kEdgeGrazeBarycentric;
}

size_t check_hits(std::string_view structure, std::string_view reference, std::span<const accel::Ray> rays,
                  std::span<const accel::Hit> reference_hits, std::span<const accel::Hit> hits) {
  if (rays.size() != reference_hits.size() || rays.size() != hits.size())
    fail("accel-bench: {} rays, {} hits of {}, {} hits of {}", rays.size(), reference_hits.size(), reference,
         hits.size(), structure);
  size_t grazes = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    if (const auto why = hit_disagreement(reference_hits[i], hits[i])) {
      if (is_edge_graze(reference_hits[i], hits[i])) {
        ++grazes;
        continue;
      }
      const accel::Ray& ray = rays[i];
      fail("accel-bench: {} disagrees with {} on ray {} (origin ({}, {}, {}), direction ({}, {}, {})): {}", structure,
           reference, i, ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z,
           *why);
    }
  }
  if (static_cast<double>(grazes) > kMaxEdgeGrazeFraction * static_cast<double>(rays.size()))
    fail("accel-bench: {} disagrees with {} on {} of {} rays, each an edge-grazing hit (barycentric < {}): more than "
         "the {} allowed",
         structure, reference, grazes, rays.size(), kEdgeGrazeBarycentric, kMaxEdgeGrazeFraction);
  return grazes;
}

}  // namespace glint::accel_bench
