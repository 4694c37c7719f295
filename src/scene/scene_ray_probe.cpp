#include "scene/scene_ray_probe.h"

#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/trace.h"
#include "accel/triangle_mesh.h"

#include <algorithm>

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
  remove_duplicate_triangles();
  bvh_ = accel::build_bvh(accel::BvhBuilder::sah, accel::make_triangle_soup(corners_));
  ray_cost_ = accel::compute_stats(bvh_).sah_cost;
}

// Copies of one triangle in the same place (instances with the same transform, a face repeated in a
// file) cannot be told apart by a BVH: every ray that reaches one tests them all, so 10^5 copies cost
// minutes. One copy answers every ray the same way. A triangle is compared with its corners rotated
// to start at the smallest, so the same winding written from another corner is the same triangle.
void SceneRayProbe::remove_duplicate_triangles() {
  const std::size_t count = corners_.size() / 3;
  const auto less = [](const vec3& a, const vec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  for (std::size_t t = 0; t < count; ++t) {
    vec3* c = &corners_[3 * t];
    const std::size_t first = less(c[1], c[0]) ? (less(c[2], c[1]) ? 2 : 1) : (less(c[2], c[0]) ? 2 : 0);
    std::rotate(c, c + first, c + 3);
  }
  std::vector<std::uint32_t> order(count);
  for (std::size_t t = 0; t < count; ++t) order[t] = static_cast<std::uint32_t>(t);
  const auto triangle_less = [&](std::uint32_t a, std::uint32_t b) {
    for (std::size_t k = 0; k < 3; ++k) {
      const vec3& p = corners_[3 * std::size_t{a} + k];
      const vec3& q = corners_[3 * std::size_t{b} + k];
      if (p != q) return less(p, q);
    }
    return a < b;  // a stable, total order: the first copy is kept
  };
  std::sort(order.begin(), order.end(), triangle_less);
  std::vector<bool> keep(count, true);
  for (std::size_t i = 1; i < count; ++i) {
    const std::size_t a = 3 * std::size_t{order[i - 1]}, b = 3 * std::size_t{order[i]};
    keep[order[i]] = !(corners_[a] == corners_[b] && corners_[a + 1] == corners_[b + 1] && corners_[a + 2] == corners_[b + 2]);
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < count; ++t) {
    if (!keep[t]) continue;
    for (std::size_t k = 0; k < 3; ++k) corners_[3 * kept + k] = corners_[3 * t + k];
    ++kept;
  }
  corners_.resize(3 * kept);
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
