#include "scene/scene_ray_probe.h"

#include "accel/builder.h"
#include "accel/trace.h"
#include "accel/triangle_mesh.h"

namespace glint {

SceneRayProbe::SceneRayProbe(const Scene& scene) {
  std::size_t triangles = 0;
  for (const Instance& instance : scene.instances)
    if (instance.mesh < scene.meshes.size()) triangles += scene.meshes[instance.mesh].triangle_count();
  corners_.reserve(3 * triangles);
  for (const Instance& instance : scene.instances) {
    if (instance.mesh >= scene.meshes.size()) continue;  // Scene::validate reports it
    const Mesh& mesh = scene.meshes[instance.mesh];
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      vec3 corner[3];
      bool usable = true;
      for (std::size_t k = 0; k < 3; ++k) {
        const std::uint32_t index = mesh.indices[i + k];
        usable = usable && index < mesh.positions.size();
        if (!usable) break;
        corner[k] = vec3(instance.transform * vec4(mesh.positions[index], 1.0f));
        usable = is_finite(corner[k]);
      }
      if (!usable) continue;  // Scene::validate reports it
      for (const vec3& p : corner) {
        corners_.push_back(p);
        bounds_.extend(p);
      }
    }
  }
  bvh_ = accel::build_bvh(accel::BvhBuilder::sah, accel::make_triangle_soup(corners_));
}

std::vector<ProbeHit> SceneRayProbe::closest(std::span<const accel::Ray> rays) const {
  std::vector<accel::Hit> hits(rays.size());
  if (!corners_.empty()) accel::trace_closest(bvh_, accel::make_triangle_soup(corners_), rays, hits);
  std::vector<ProbeHit> result(rays.size());
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (!hits[i].valid()) continue;
    ProbeHit& probe = result[i];
    probe.hit = true;
    probe.distance = hits[i].t;
    probe.triangle = hits[i].prim;
    const vec3* corner = &corners_[3 * static_cast<std::size_t>(hits[i].prim)];
    probe.point = (1.0f - hits[i].u - hits[i].v) * corner[0] + hits[i].u * corner[1] + hits[i].v * corner[2];
    // In double: a triangle far from the origin has short edges relative to its coordinates.
    const glm::dvec3 a(corner[0]), b(corner[1]), c(corner[2]);
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    if (length > 0.0) probe.normal = vec3(n / length);
  }
  return result;
}

}  // namespace glint
