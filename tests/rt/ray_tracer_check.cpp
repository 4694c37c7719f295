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
#include <utility>

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

Scene make_strongly_deforming_scene() {
  Scene scene = make_instanced_scene(16);
  SineDeform& wave = *scene.meshes[2].deform;
  wave.amplitude = 1.0f;
  wave.frequency = 25.0f;
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

std::vector<uint8_t> brute_force_occluded(const Scene& scene, std::span<const accel::Ray> rays) {
  const rt::SceneGeometry geometry = rt::flatten_scene(scene);
  const accel::TriangleMesh mesh = geometry.mesh();
  std::vector<uint8_t> occluded(rays.size(), 0);
  for (size_t i = 0; i < rays.size(); ++i) {
    const accel::WatertightRay watertight = accel::make_watertight_ray(rays[i].origin, rays[i].direction);
    for (uint32_t t = 0; t < mesh.triangle_count && occluded[i] == 0; ++t) {
      accel::TriangleHit hit{};
      if (accel::intersect_triangle(watertight, mesh.triangle(t), rays[i].t_min, rays[i].t_max, hit)) occluded[i] = 1;
    }
  }
  return occluded;
}

std::vector<uint8_t> trace_occluded(const rt::RayTracer& tracer, std::span<const accel::Ray> rays) {
  // Filled with a value trace_any never writes, so a ray it skipped shows up as a difference.
  std::vector<uint8_t> occluded(rays.size(), 0xAB);
  tracer.trace_any(rays, occluded);
  return occluded;
}

std::vector<uint8_t> hit_exists(std::span<const accel::Hit> hits) {
  std::vector<uint8_t> exists(hits.size());
  for (size_t i = 0; i < hits.size(); ++i) exists[i] = hits[i].valid() ? 1 : 0;
  return exists;
}

std::string compare_occluded(std::span<const accel::Ray> rays, std::span<const uint8_t> expected,
                             std::span<const uint8_t> actual) {
  if (expected.size() != rays.size() || actual.size() != rays.size()) return "size mismatch";
  std::string report;
  size_t differences = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    if (expected[i] == actual[i]) continue;
    if (++differences <= 5) {
      const accel::Ray& ray = rays[i];
      report += fmt::format("ray {}: expected {}, got {} (origin {} {} {}, direction {} {} {}, t [{}, {}])\n", i,
                            expected[i], actual[i], ray.origin.x, ray.origin.y, ray.origin.z, ray.direction.x,
                            ray.direction.y, ray.direction.z, ray.t_min, ray.t_max);
    }
  }
  if (differences > 0) report += fmt::format("{} of {} rays differ", differences, rays.size());
  return report;
}

std::vector<accel::Ray> hit_interval_probe_rays(std::span<const accel::Ray> rays, std::span<const accel::Hit> hits) {
  std::vector<accel::Ray> probes;
  for (size_t i = 0; i < rays.size() && i < hits.size(); ++i) {
    if (!hits[i].valid() || !(hits[i].t > 0.0f)) continue;
    const float t = hits[i].t;
    accel::Ray before = rays[i];
    before.t_max = t * (1.0f - 1e-3f);
    accel::Ray after = rays[i];
    after.t_max = t * (1.0f + 1e-3f);
    accel::Ray past = rays[i];
    past.t_min = t * (1.0f + 1e-3f);
    if (before.t_max >= before.t_min) probes.push_back(before);
    probes.push_back(after);
    if (past.t_min <= past.t_max) probes.push_back(past);
  }
  return probes;
}

std::vector<accel::Ray> edge_and_vertex_rays(const Scene& scene, size_t max_per_kind, uint32_t seed) {
  const rt::SceneGeometry geometry = rt::flatten_scene(scene);
  // Per edge ((lower, higher) world vertex index) and per vertex: the unit normals of the triangles
  // around it (the meshes are consistently oriented, so a ray crossing all of them on the same side
  // passes through the surface there).
  std::map<std::pair<uint32_t, uint32_t>, std::vector<vec3>> edge_normals;
  std::vector<std::vector<vec3>> vertex_normals(geometry.positions.size());
  for (uint32_t t = 0; t < geometry.triangle_count(); ++t) {
    const uint32_t* corner = &geometry.indices[3 * static_cast<size_t>(t)];
    const vec3 n = glm::cross(geometry.positions[corner[1]] - geometry.positions[corner[0]],
                              geometry.positions[corner[2]] - geometry.positions[corner[0]]);
    if (!(glm::length(n) > 0.0f)) continue;
    for (int k = 0; k < 3; ++k) {
      const uint32_t a = corner[k], b = corner[(k + 1) % 3];
      edge_normals[{std::min(a, b), std::max(a, b)}].push_back(glm::normalize(n));
      vertex_normals[a].push_back(glm::normalize(n));
    }
  }
  // Interior edges are shared by exactly two triangles; interior vertices have only interior edges.
  std::vector<int> vertex_state(geometry.positions.size(), 0);  // 0 unused, 1 interior, -1 on a border
  std::vector<std::pair<vec3, const std::vector<vec3>*>> edge_targets, vertex_targets;
  for (const auto& [edge, normals] : edge_normals) {
    const bool interior = normals.size() == 2;
    for (uint32_t v : {edge.first, edge.second}) {
      if (!interior) vertex_state[v] = -1;
      else if (vertex_state[v] == 0) vertex_state[v] = 1;
    }
    if (interior) edge_targets.push_back({0.5f * (geometry.positions[edge.first] + geometry.positions[edge.second]), &normals});
  }
  for (size_t v = 0; v < vertex_state.size(); ++v)
    if (vertex_state[v] == 1) vertex_targets.push_back({geometry.positions[v], &vertex_normals[v]});
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  std::vector<accel::Ray> rays;
  for (auto* kind : {&edge_targets, &vertex_targets}) {
    std::shuffle(kind->begin(), kind->end(), rng);
    size_t taken = 0;
    for (const auto& [point, normals] : *kind) {
      if (taken == max_per_kind) break;
      // A direction off the surface on the same side of every triangle around the target, at least
      // 0.3 from grazing any of them; targets where none is found quickly are skipped.
      for (int attempt = 0; attempt < 64; ++attempt) {
        const vec3 d(gauss(rng), gauss(rng), gauss(rng));
        if (glm::length(d) < 1e-3f) continue;
        const vec3 away = glm::normalize(d);
        bool front = true, back = true;
        for (const vec3& n : *normals) {
          front = front && glm::dot(away, n) >= 0.3f;
          back = back && glm::dot(away, n) <= -0.3f;
        }
        if (!front && !back) continue;
        accel::Ray ray;
        ray.origin = point + (0.5f + 2.5f * unit(rng)) * away;
        ray.direction = point - ray.origin;  // reaches the target at t = 1
        rays.push_back(ray);
        ++taken;
        break;
      }
    }
  }
  return rays;
}

std::vector<accel::Ray> occlusion_test_rays(const Scene& scene, size_t random_count, uint32_t seed) {
  std::vector<accel::Ray> rays = random_rays(scene, random_count, seed);
  const std::vector<accel::Ray> edges = edge_and_vertex_rays(scene, random_count / 4, seed + 1);
  rays.insert(rays.end(), edges.begin(), edges.end());
  const std::vector<accel::Ray> probes = hit_interval_probe_rays(rays, brute_force_hits(scene, rays));
  rays.insert(rays.end(), probes.begin(), probes.end());
  return rays;
}

}  // namespace glint::testing
