#include "optix/optix_test_support.h"

#include "rt/ray_tracer_check.h"
#include "rt/scene_geometry.h"

#include <fmt/format.h>

#include <algorithm>

namespace glint::testing {
namespace {

bool near_an_edge(const accel::Hit& hit, float edge_band) {
  return hit.valid() && std::min({hit.u, hit.v, 1.0f - hit.u - hit.v}) < edge_band;
}

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
  const EdgeFilteredHits kept = without_edge_grazing_rays(rays, expected, actual);
  if (kept.set_aside * 200 > rays.size())
    return fmt::format("{} of {} rays graze an edge: too many to set aside", kept.set_aside, rays.size());
  return compare_hits(scene, kept.rays, kept.expected, kept.actual);
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
