#include "optix/test_support.h"

#include "rt/ray_tracer_check.h"
#include "rt/scene_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace glint::testing {
namespace {

bool near_an_edge(const accel::Hit& hit, float edge_band) {
  return hit.valid() && std::min({hit.u, hit.v, 1.0f - hit.u - hit.v}) < edge_band;
}

// The cosine between the ray and its hit triangle's world normal: near 0 the ray skims the surface,
// t and u, v are ill-conditioned, and two correct tests (OptiX's, glint's watertight one) round apart
// (seen: rays leaving a surface that hit the next triangle of the same mesh a few mm on).
float hit_cosine(const Scene& scene, const accel::Ray& ray, const accel::Hit& hit) {
  if (!hit.valid()) return 1.0f;
  const Instance& instance = scene.instances[hit.instance];
  const Mesh& mesh = scene.meshes[instance.mesh];
  vec3 corner[3];
  for (int k = 0; k < 3; ++k)
    corner[k] = vec3(instance.transform * vec4(mesh.positions[mesh.indices[3 * hit.prim + k]], 1.0f));
  const vec3 normal = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
  const float lengths = glm::length(normal) * glm::length(ray.direction);
  return lengths > 0.0f ? std::abs(glm::dot(normal, ray.direction)) / lengths : 0.0f;
}

constexpr float kGrazingCosine = 0.02f;  // about 1.1 degrees off the surface
constexpr float kBarycentricSlack = 1e-2f;

}  // namespace

EdgeFilteredHits without_edge_grazing_rays(std::span<const accel::Ray> rays, std::span<const accel::Hit> expected,
                                           std::span<const accel::Hit> actual, float edge_band) {
  EdgeFilteredHits kept;
  for (std::size_t i = 0; i < rays.size() && i < expected.size() && i < actual.size(); ++i) {
    if (near_an_edge(expected[i], edge_band) || near_an_edge(actual[i], edge_band)) {
      ++kept.set_aside;
      continue;
    }
    kept.rays.push_back(rays[i]);
    kept.expected.push_back(expected[i]);
    kept.actual.push_back(actual[i]);
  }
  return kept;
}

std::string compare_hits_off_edges(const Scene& scene, std::span<const accel::Ray> rays,
                                   std::span<const accel::Hit> expected, std::span<const accel::Hit> actual) {
  if (expected.size() != rays.size() || actual.size() != rays.size()) return "size mismatch";
  EdgeFilteredHits kept = without_edge_grazing_rays(rays, expected, actual);
  EdgeFilteredHits off_surface;
  off_surface.set_aside = kept.set_aside;
  for (std::size_t i = 0; i < kept.rays.size(); ++i) {
    if (hit_cosine(scene, kept.rays[i], kept.expected[i]) < kGrazingCosine ||
        hit_cosine(scene, kept.rays[i], kept.actual[i]) < kGrazingCosine) {
      ++off_surface.set_aside;
      continue;
    }
    off_surface.rays.push_back(kept.rays[i]);
    off_surface.expected.push_back(kept.expected[i]);
    accel::Hit actual_hit = kept.actual[i];
    // Same triangle at the same t: OptiX rounds its barycentrics differently, and on a small or thin
    // triangle they may differ by more than compare_hits' 1e-3 (seen: 1e-3..1e-2 on a dinosaur).
    const accel::Hit& expected_hit = kept.expected[i];
    if (actual_hit.valid() && expected_hit.valid() && actual_hit.instance == expected_hit.instance &&
        actual_hit.prim == expected_hit.prim &&
        std::abs(actual_hit.t - expected_hit.t) <= 1e-4f * std::abs(expected_hit.t) &&
        std::abs(actual_hit.u - expected_hit.u) < kBarycentricSlack &&
        std::abs(actual_hit.v - expected_hit.v) < kBarycentricSlack) {
      actual_hit.u = expected_hit.u;
      actual_hit.v = expected_hit.v;
    }
    off_surface.actual.push_back(actual_hit);
  }
  if (off_surface.set_aside * 200 > rays.size())
    return fmt::format("{} of {} rays graze an edge or skim a surface: too many to set aside", off_surface.set_aside,
                       rays.size());
  return compare_hits(scene, off_surface.rays, off_surface.expected, off_surface.actual);
}

Scene flattened_single_mesh_scene(const Scene& scene) {
  const rt::SceneGeometry geometry = rt::flatten_scene(scene);
  Scene flat = scene;
  Mesh mesh;
  mesh.name = "world";
  mesh.positions = geometry.positions;
  mesh.normals.assign(geometry.positions.size(), vec3(0.0f, 1.0f, 0.0f));  // unused by tracing
  mesh.indices = geometry.indices;
  flat.meshes = {mesh};
  flat.instances = {{"world", 0, mat4(1.0f)}};
  return flat;
}

}  // namespace glint::testing
