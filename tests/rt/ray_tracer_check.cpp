#include "rt/ray_tracer_check.h"

#include "accel/intersect_triangle.h"
#include "rt/scene_geometry.h"
#include "rt/tiny_scene.h"
#include "scene/presets.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>

namespace glint::testing {
namespace {

Mesh tetrahedron() {
  Mesh mesh;
  mesh.name = "tetra";
  mesh.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1)};
  for (const vec3& p : mesh.positions) mesh.normals.push_back(glm::normalize(p - vec3(0.25f)));
  mesh.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  mesh.material = 1;
  return mesh;
}

bool tolerably_equal(float a, float b) { return std::abs(a - b) <= 1e-4f * std::max(1.0f, std::abs(b)); }

// The world-space t of world triangle `triangle` on `ray` over the ray's whole interval.
std::optional<accel::TriangleHit> hit_triangle(const accel::TriangleMesh& mesh, uint32_t triangle, const accel::Ray& ray) {
  const accel::WatertightRay watertight = accel::make_watertight_ray(ray.origin, ray.direction);
  accel::TriangleHit hit{};
  if (!accel::intersect_triangle(watertight, mesh.triangle(triangle), ray.t_min, ray.t_max, hit)) return std::nullopt;
  return hit;
}

}  // namespace

Scene make_instanced_scene(int sheet_cells) {
  Scene scene = make_tiny_scene(sheet_cells);
  const mat4 skew = glm::scale(glm::rotate(glm::translate(mat4(1.0f), vec3(0.5f, 3, -2)), glm::radians(35.0f),
                                           glm::normalize(vec3(1, 2, 0.5f))),
                               vec3(1.5f, 0.7f, 2.0f));
  scene.instances.push_back({"sheet c", 2, skew});
  scene.meshes.push_back(tetrahedron());
  const auto tetra = static_cast<uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back({"tetra a", tetra, glm::translate(mat4(1.0f), vec3(-4, 0.5f, 2))});
  scene.instances.push_back(
      {"tetra b", tetra,
       glm::scale(glm::rotate(glm::translate(mat4(1.0f), vec3(1, 2, 3)), glm::radians(-60.0f), vec3(0, 0, 1)),
                  vec3(2.0f, 1.0f, 0.5f))});
  scene.validate();
  return scene;
}

Scene make_reduced_atrium(size_t max_deformable_instances) {
  const Scene full = make_preset("atrium-simple");
  Scene scene = full;
  scene.meshes.clear();
  scene.instances.clear();
  std::map<uint32_t, uint32_t> new_index;
  size_t deformable_instances = 0;
  for (const Instance& instance : full.instances) {
    const Mesh& mesh = full.meshes[instance.mesh];
    const bool architecture = mesh.name == "walls" || mesh.name == "beams";
    if (mesh.deformable) {
      if (deformable_instances == max_deformable_instances) continue;
      ++deformable_instances;
    } else if (!architecture) {
      continue;
    }
    auto [it, added] = new_index.try_emplace(instance.mesh, static_cast<uint32_t>(scene.meshes.size()));
    if (added) scene.meshes.push_back(mesh);
    Instance kept = instance;
    kept.mesh = it->second;
    scene.instances.push_back(kept);
  }
  scene.validate();
  return scene;
}

std::vector<accel::Ray> random_rays(const Scene& scene, size_t count, uint32_t seed) {
  const Aabb bounds = scene.world_bounds();
  const vec3 margin = 0.05f * (bounds.max - bounds.min);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  std::vector<accel::Ray> rays(count);
  for (size_t i = 0; i < count; ++i) {
    accel::Ray& ray = rays[i];
    const vec3 lo = bounds.min - margin, hi = bounds.max + margin;
    ray.origin = lo + vec3(unit(rng), unit(rng), unit(rng)) * (hi - lo);
    vec3 d(gauss(rng), gauss(rng), gauss(rng));
    if (glm::length(d) < 1e-3f) d = vec3(0, -1, 0);
    ray.direction = glm::normalize(d) * (0.5f + 1.5f * unit(rng));
    if (i % 4 == 3) ray.t_max = 0.3f * glm::length(hi - lo) * unit(rng);
  }
  return rays;
}

std::vector<accel::Hit> brute_force_hits(const Scene& scene, std::span<const accel::Ray> rays) {
  const rt::SceneGeometry geometry = rt::flatten_scene(scene);
  const accel::TriangleMesh mesh = geometry.mesh();
  std::vector<accel::Hit> hits(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) {
    const accel::Ray& ray = rays[i];
    const accel::WatertightRay watertight = accel::make_watertight_ray(ray.origin, ray.direction);
    accel::Hit best;
    for (uint32_t t = 0; t < mesh.triangle_count; ++t) {
      accel::TriangleHit hit{};
      if (!accel::intersect_triangle(watertight, mesh.triangle(t), ray.t_min, std::min(ray.t_max, best.t), hit)) continue;
      if (hit.t >= best.t) continue;
      best.t = hit.t;
      best.instance = geometry.sources[t].instance;
      best.prim = geometry.sources[t].local_triangle;
      best.u = hit.u;
      best.v = hit.v;
    }
    hits[i] = best;
  }
  return hits;
}

std::string compare_hits(const Scene& scene, std::span<const accel::Ray> rays, std::span<const accel::Hit> expected,
                         std::span<const accel::Hit> hits) {
  if (expected.size() != rays.size() || hits.size() != rays.size()) return "size mismatch";
  const rt::SceneGeometry geometry = rt::flatten_scene(scene);
  const accel::TriangleMesh mesh = geometry.mesh();
  std::vector<uint32_t> first_triangle(scene.instances.size());
  for (const rt::InstanceRange& range : geometry.instances) first_triangle[range.instance] = range.first_triangle;
  std::string report;
  size_t differences = 0;
  const auto note = [&](size_t i, const std::string& what) {
    if (++differences <= 5)
      report += fmt::format("ray {}: {} (expected t {} instance {} prim {}, got t {} instance {} prim {})\n", i, what,
                            expected[i].t, expected[i].instance, expected[i].prim, hits[i].t, hits[i].instance,
                            hits[i].prim);
  };
  for (size_t i = 0; i < rays.size(); ++i) {
    const accel::Hit& want = expected[i];
    const accel::Hit& got = hits[i];
    if (want.valid() != got.valid()) {
      note(i, "hit/miss differs");
      continue;
    }
    if (!want.valid()) continue;
    if (!tolerably_equal(got.t, want.t)) {
      note(i, "t differs");
      continue;
    }
    if (got.instance >= scene.instances.size() ||
        got.prim >= scene.meshes[scene.instances[got.instance].mesh].triangle_count()) {
      note(i, "instance or prim out of range");
      continue;
    }
    const auto own = hit_triangle(mesh, first_triangle[got.instance] + got.prim, rays[i]);
    if (got.instance != want.instance || got.prim != want.prim) {
      // Another triangle at the same distance (a shared edge, coplanar copies) is a tie, not an error.
      if (!own || !tolerably_equal(own->t, want.t)) note(i, "different triangle, not a tie");
      continue;
    }
    if (std::abs(got.u - want.u) > 1e-3f || std::abs(got.v - want.v) > 1e-3f) note(i, "u, v differ");
  }
  if (differences > 0) report += fmt::format("{} of {} rays differ", differences, rays.size());
  return report;
}

std::vector<accel::Hit> trace(const rt::RayTracer& tracer, std::span<const accel::Ray> rays) {
  std::vector<accel::Hit> hits(rays.size());
  tracer.trace_closest(rays, hits);
  return hits;
}

}  // namespace glint::testing
