#include "app/accel_bench/hit_check.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace glint::accel_bench {
namespace {

float max_abs(const vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

float edge_distance(const accel::Hit& hit) { return std::min({hit.u, hit.v, 1.0f - hit.u - hit.v}); }

// The incidence cosine of a hit's triangle, or nullopt when the scene has no such triangle.
std::optional<float> hit_cosine(const accel::Ray& ray, const accel::Hit& hit, const HitGeometry& geometry) {
  if (hit.prim >= geometry.mesh.triangle_count) return std::nullopt;
  return incidence_cosine(ray, geometry.mesh.triangle(hit.prim));
}

// The tolerance of one hit on its own triangle (0 for a triangle the scene does not have).
float own_tolerance(const accel::Ray& ray, const accel::Hit& hit, const HitGeometry& geometry) {
  const std::optional<float> cosine = hit_cosine(ray, hit, geometry);
  return cosine ? hit_t_tolerance(ray, geometry.magnitude, *cosine) : 0.0f;
}

}  // namespace

HitGeometry hit_geometry(const accel::TriangleMesh& mesh) {
  const size_t vertices = mesh.indices != nullptr ? mesh.vertex_count : 3 * static_cast<size_t>(mesh.triangle_count);
  float magnitude = 0.0f;
  for (size_t i = 0; i < vertices; ++i) magnitude = std::max(magnitude, max_abs(mesh.positions[i]));
  return {mesh, magnitude};
}

float incidence_cosine(const accel::Ray& ray, const accel::Triangle& triangle) {
  const vec3 normal = glm::cross(triangle.v1 - triangle.v0, triangle.v2 - triangle.v0);
  const float lengths = glm::length(normal) * glm::length(ray.direction);
  const float cosine = lengths > 0.0f ? std::abs(glm::dot(normal, ray.direction)) / lengths : 0.0f;
  return std::isfinite(cosine) ? std::min(cosine, 1.0f) : 0.0f;
}

float hit_t_tolerance(const accel::Ray& ray, float magnitude, float incidence_cosine) {
  const float coordinates = std::max(magnitude, max_abs(ray.origin));
  return kHitToleranceUlps * FLT_EPSILON * coordinates /
         (glm::length(ray.direction) * std::max(incidence_cosine, kMinIncidenceCosine));
}

std::optional<std::string> hit_disagreement(const accel::Ray& ray, const accel::Hit& reference, const accel::Hit& actual,
                                            const HitGeometry& geometry) {
  if (reference.valid() != actual.valid()) {
    // A hit this close to an end of the ray's range may have come out just outside it in the other.
    const accel::Hit& only = reference.valid() ? reference : actual;
    const float tolerance = own_tolerance(ray, only, geometry);
    if (only.t - ray.t_min <= tolerance || ray.t_max - only.t <= tolerance) return std::nullopt;
    return reference.valid() ? fmt::format("missed, the reference hits triangle {} at t {}", reference.prim, reference.t)
                             : fmt::format("hit triangle {} at t {}, the reference misses", actual.prim, actual.t);
  }
  if (!reference.valid()) return std::nullopt;
  const std::optional<float> reference_cosine = hit_cosine(ray, reference, geometry);
  const std::optional<float> cosine = hit_cosine(ray, actual, geometry);
  if (!reference_cosine || !cosine)
    return fmt::format("hit triangle {}, the reference triangle {}, of a scene of {} triangles", actual.prim,
                       reference.prim, geometry.mesh.triangle_count);
  // The same rule for the same triangle and for another one (a tie): either may be right.
  const float tolerance = hit_t_tolerance(ray, geometry.magnitude, std::min(*reference_cosine, *cosine));
  // The nearer hit this close to t_min: the other may have put it just before t_min and gone on.
  const accel::Hit& nearer = reference.t < actual.t ? reference : actual;
  if (std::abs(reference.t - actual.t) > tolerance && nearer.t - ray.t_min > own_tolerance(ray, nearer, geometry))
    return fmt::format("hit triangle {} at t {}, the reference hits triangle {} at t {} (more than {:.3g} apart)",
                       actual.prim, actual.t, reference.prim, reference.t, tolerance);
  return std::nullopt;
}

bool is_edge_graze(const accel::Hit& reference, const accel::Hit& actual) {
  // The hit the other one missed is the nearer one (or the only one).
  const accel::Hit* missed = nullptr;
  if (reference.valid() && (!actual.valid() || reference.t < actual.t)) missed = &reference;
  if (actual.valid() && (!reference.valid() || actual.t < reference.t)) missed = &actual;
  return missed != nullptr && edge_distance(*missed) < kEdgeGrazeBarycentric;
}

HitCheck check_hits(std::string_view structure, std::string_view reference, std::span<const accel::Ray> rays,
                    std::span<const accel::Hit> reference_hits, std::span<const accel::Hit> hits,
                    const HitGeometry& geometry) {
  if (rays.size() != reference_hits.size() || rays.size() != hits.size())
    fail("accel-bench: {} rays, {} hits of {}, {} hits of {}", rays.size(), reference_hits.size(), reference,
         hits.size(), structure);
  HitCheck check;
  std::string first;
  for (size_t i = 0; i < rays.size(); ++i) {
    const std::optional<std::string> why = hit_disagreement(rays[i], reference_hits[i], hits[i], geometry);
    if (!why) continue;
    if (is_edge_graze(reference_hits[i], hits[i])) {
      ++check.edge_grazes;
      continue;
    }
    if (check.disagreements++ == 0) {
      const accel::Ray& ray = rays[i];
      first = fmt::format("ray {} (origin ({}, {}, {}), direction ({}, {}, {})): {}", i, ray.origin.x, ray.origin.y,
                          ray.origin.z, ray.direction.x, ray.direction.y, ray.direction.z, *why);
    }
  }
  if (check.disagreements != 0)
    check.problem = fmt::format("{} disagrees with {} on {} of {} rays; first: {}", structure, reference,
                                check.disagreements, rays.size(), first);
  else if (static_cast<double>(check.edge_grazes) > kMaxEdgeGrazeFraction * static_cast<double>(rays.size()))
    check.problem = fmt::format(
        "{} disagrees with {} on {} of {} rays, each an edge-grazing hit (barycentric < {}): more than the {} allowed",
        structure, reference, check.edge_grazes, rays.size(), kEdgeGrazeBarycentric, kMaxEdgeGrazeFraction);
  return check;
}

}  // namespace glint::accel_bench
