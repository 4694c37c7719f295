#include "test_scenes.h"

#include "accel/intersect_triangle.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace glint::accel::testing {
namespace {

vec3 uniform_in(std::mt19937& rng, const vec3& lo, const vec3& hi) {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  return lo + vec3(u(rng), u(rng), u(rng)) * (hi - lo);
}

vec3 random_direction(std::mt19937& rng) {
  std::normal_distribution<float> n(0.0f, 1.0f);
  for (;;) {
    const vec3 d(n(rng), n(rng), n(rng));
    if (glm::dot(d, d) > 1e-6f) return glm::normalize(d);
  }
}

}  // namespace

uint32_t TestMesh::add_vertex(const vec3& p) {
  positions.push_back(p);
  return static_cast<uint32_t>(positions.size() - 1);
}

void TestMesh::add_triangle(const vec3& a, const vec3& b, const vec3& c) {
  const uint32_t ia = add_vertex(a), ib = add_vertex(b), ic = add_vertex(c);
  add_triangle(ia, ib, ic);
}

void TestMesh::add_triangle(uint32_t a, uint32_t b, uint32_t c) {
  indices.insert(indices.end(), {a, b, c});
}

Aabb TestMesh::bounds() const {
  Aabb box;
  for (const vec3& p : positions) box.extend(p);
  return box;
}

TestMesh make_random_soup(uint32_t seed, uint32_t triangle_count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  TestMesh mesh;
  while (mesh.triangle_count() < triangle_count) {
    const float kind = u(rng);
    if (kind < 0.78f || mesh.triangle_count() < 8) {  // small
      const vec3 center = uniform_in(rng, vec3(-1.0f), vec3(1.0f));
      mesh.add_triangle(center + 0.05f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)),
                        center + 0.05f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)),
                        center + 0.05f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)));
    } else if (kind < 0.80f) {  // huge
      mesh.add_triangle(uniform_in(rng, vec3(-3.0f), vec3(3.0f)), uniform_in(rng, vec3(-3.0f), vec3(3.0f)),
                        uniform_in(rng, vec3(-3.0f), vec3(3.0f)));
    } else if (kind < 0.90f) {  // axis-aligned, on a few shared planes so some overlap
      const int axis = static_cast<int>(u(rng) * 3.0f) % 3;
      const float plane = std::round(u(rng) * 8.0f - 4.0f) * 0.25f;
      const vec3 center = uniform_in(rng, vec3(-1.0f), vec3(1.0f));
      vec3 p[3];
      for (vec3& q : p) {
        q = center + 0.2f * uniform_in(rng, vec3(-1.0f), vec3(1.0f));
        q[axis] = plane;
      }
      // A right triangle with edges along the other two axes: its box is flat too.
      if (u(rng) < 0.5f) {
        const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
        p[1][a1] = p[0][a1];
        p[2][a2] = p[0][a2];
      }
      mesh.add_triangle(p[0], p[1], p[2]);
    } else {  // duplicate of an earlier triangle
      const uint32_t source = static_cast<uint32_t>(u(rng) * static_cast<float>(mesh.triangle_count() - 1));
      const uint32_t* tri = &mesh.indices[3 * size_t{source}];
      const uint32_t a = tri[0], b = tri[1], c = tri[2];
      const float how = u(rng);
      if (how < 0.4f) {
        mesh.add_triangle(a, b, c);
      } else if (how < 0.7f) {
        mesh.add_triangle(c, b, a);  // flipped winding
      } else {
        const vec3 pa = mesh.positions[a], pb = mesh.positions[b], pc = mesh.positions[c];
        mesh.add_triangle(pa, pb, pc);
      }
    }
  }
  return mesh;
}

TestMesh make_grid(uint32_t cells, bool tilted) {
  TestMesh mesh;
  const uint32_t side = cells + 1;
  for (uint32_t y = 0; y < side; ++y) {
    for (uint32_t x = 0; x < side; ++x) {
      const auto fx = static_cast<float>(x), fy = static_cast<float>(y);
      mesh.add_vertex(vec3(fx, fy, tilted ? 0.37f * fx - 0.21f * fy : 0.0f));
    }
  }
  for (uint32_t y = 0; y < cells; ++y) {
    for (uint32_t x = 0; x < cells; ++x) {
      const uint32_t v00 = y * side + x, v10 = v00 + 1, v01 = v00 + side, v11 = v01 + 1;
      // Alternate the diagonal so vertices are shared by 4, 6 or 8 triangles.
      if ((x + y) % 2 == 0) {
        mesh.add_triangle(v00, v10, v11);
        mesh.add_triangle(v00, v11, v01);
      } else {
        mesh.add_triangle(v00, v10, v01);
        mesh.add_triangle(v10, v11, v01);
      }
    }
  }
  return mesh;
}

TestMesh make_clustered(uint32_t seed, uint32_t triangle_count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> n(0.0f, 1.0f);
  struct Cluster {
    vec3 center;
    float spread;
    float size;
  };
  std::vector<Cluster> clusters;
  for (int i = 0; i < 12; ++i)
    clusters.push_back({uniform_in(rng, vec3(-50.0f), vec3(50.0f)), std::pow(10.0f, u(rng) * 2.0f - 1.5f),
                        std::pow(10.0f, u(rng) * 2.0f - 3.0f)});
  TestMesh mesh;
  while (mesh.triangle_count() < triangle_count) {
    const Cluster& c = clusters[mesh.triangle_count() % clusters.size()];
    const vec3 center = c.center + c.spread * vec3(n(rng), n(rng), n(rng));
    mesh.add_triangle(center + c.size * random_direction(rng), center + c.size * random_direction(rng),
                      center + c.size * random_direction(rng));
  }
  return mesh;
}

TestMesh make_degenerate_soup(uint32_t seed, uint32_t triangle_count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::uniform_int_distribution<int> sixty_fourths(1, 64);
  TestMesh mesh;
  // Dyadic centre and offsets: centre +- offset is exact in float, so every box of the kind below
  // has exactly this centre.
  const vec3 shared_center(0.5f, 0.25f, -0.75f);
  while (mesh.triangle_count() < triangle_count) {
    const float kind = u(rng);
    const vec3 center = uniform_in(rng, vec3(-1.0f), vec3(1.0f));
    if (kind < 0.15f || mesh.triangle_count() < 4) {  // zero area
      const vec3 a = center, b = center + 0.1f * uniform_in(rng, vec3(-1.0f), vec3(1.0f));
      const float how = u(rng);
      if (how < 0.3f) {
        mesh.add_triangle(a, a, b);  // repeated corner
      } else if (how < 0.6f) {
        mesh.add_triangle(a, 0.5f * (a + b), b);  // collinear
      } else if (how < 0.8f) {
        mesh.add_triangle(a, a, a);  // a point
      } else {
        const uint32_t i = mesh.add_vertex(a), j = mesh.add_vertex(b);
        mesh.add_triangle(i, j, i);  // repeated index
      }
    } else if (kind < 0.35f) {  // coplanar and overlapping: all on z = 0.125 near the origin
      vec3 p[3];
      for (vec3& q : p) q = vec3(0.3f * (u(rng) - 0.5f), 0.3f * (u(rng) - 0.5f), 0.125f);
      mesh.add_triangle(p[0], p[1], p[2]);
    } else if (kind < 0.50f) {  // exact duplicate of an earlier triangle, by index or by value
      const auto source = static_cast<uint32_t>(u(rng) * static_cast<float>(mesh.triangle_count() - 1));
      const uint32_t* tri = &mesh.indices[3 * size_t{source}];
      const uint32_t a = tri[0], b = tri[1], c = tri[2];
      if (u(rng) < 0.5f) {
        mesh.add_triangle(a, b, c);
      } else {
        const vec3 pa = mesh.positions[a], pb = mesh.positions[b], pc = mesh.positions[c];
        mesh.add_triangle(pa, pb, pc);
      }
    } else if (kind < 0.53f) {  // huge
      mesh.add_triangle(uniform_in(rng, vec3(-1e3f), vec3(1e3f)), uniform_in(rng, vec3(-1e3f), vec3(1e3f)),
                        uniform_in(rng, vec3(-1e3f), vec3(1e3f)));
    } else if (kind < 0.68f) {  // tiny
      mesh.add_triangle(center + 1e-5f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)),
                        center + 1e-5f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)),
                        center + 1e-5f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)));
    } else if (kind < 0.78f) {  // identical centroids: the box is shared_center +- (sx, sy, sz)
      const auto step = [&] { return static_cast<float>(sixty_fourths(rng)) / 64.0f; };
      const float sx = step(), sy = step(), sz = step();
      const float fx = (u(rng) < 0.5f ? -1.0f : 1.0f) * sx * 0.5f, fy = (u(rng) < 0.5f ? -1.0f : 1.0f) * sy * 0.5f;
      mesh.add_triangle(shared_center + vec3(sx, sy, sz), shared_center + vec3(-sx, -sy, sz),
                        shared_center + vec3(fx, fy, -sz));
    } else {  // ordinary small triangle
      mesh.add_triangle(center + 0.05f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)),
                        center + 0.05f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)),
                        center + 0.05f * uniform_in(rng, vec3(-1.0f), vec3(1.0f)));
    }
  }
  return mesh;
}

std::vector<Ray> make_random_rays(const TestMesh& mesh, uint32_t seed, size_t count, const RayOptions& options) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const Aabb box = mesh.bounds();
  const vec3 margin = 0.5f * box.extent() + vec3(1e-3f);
  const TriangleMesh view = mesh.view();
  std::vector<Ray> rays(count);
  const auto random_target = [&] {
    const auto prim = static_cast<uint32_t>(u(rng) * static_cast<float>(view.triangle_count)) % view.triangle_count;
    const Triangle tri = view.triangle(prim);
    float b1 = u(rng), b2 = u(rng);
    if (b1 + b2 > 1.0f) {
      b1 = 1.0f - b1;
      b2 = 1.0f - b2;
    }
    return (1.0f - b1 - b2) * tri.v0 + b1 * tri.v1 + b2 * tri.v2;
  };
  for (Ray& ray : rays) {
    ray.origin = uniform_in(rng, box.min - margin, box.max + margin);
    const bool aimed = u(rng) < options.aimed_fraction && view.triangle_count > 0;
    const float kind = u(rng);
    if (kind < options.axis_aligned_fraction + options.zero_component_fraction) {
      if (kind < options.axis_aligned_fraction) {
        ray.direction = vec3(0.0f);
        ray.direction[static_cast<int>(u(rng) * 3.0f) % 3] = u(rng) < 0.5f ? -1.0f : 1.0f;
      } else {
        ray.direction = random_direction(rng);
        ray.direction[static_cast<int>(u(rng) * 3.0f) % 3] = 0.0f;
      }
      // Aimed: start behind a point of a triangle, so the direction keeps its zero components.
      if (aimed) ray.origin = random_target() - (0.1f + u(rng)) * glm::length(box.extent()) * ray.direction;
    } else if (aimed) {
      ray.direction = random_target() - ray.origin;  // unnormalised on purpose: t = 1 at the target
      if (glm::dot(ray.direction, ray.direction) == 0.0f) ray.direction = vec3(0.0f, 0.0f, 1.0f);
    } else {
      ray.direction = random_direction(rng);
    }
    if (u(rng) < options.limited_fraction) {
      const float scale = glm::length(box.extent()) / glm::length(ray.direction);
      ray.t_min = u(rng) * 0.5f * scale;
      ray.t_max = ray.t_min + u(rng) * scale;
    }
  }
  return rays;
}

std::vector<Ray> make_grid_edge_rays(const TestMesh& grid, uint32_t cells, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const uint32_t side = cells + 1;
  std::vector<Ray> rays;
  // Interior only, so that every target is surrounded by triangles.
  for (uint32_t y = 1; y + 1 < side; ++y) {
    for (uint32_t x = 1; x + 1 < side; ++x) {
      const vec3 v = grid.positions[y * side + x];
      const vec3 right = grid.positions[y * side + x + 1];
      const vec3 up = grid.positions[(y + 1) * side + x];
      const vec3 diagonal = grid.positions[(y + 1) * side + x + 1];
      for (const vec3& target : {v, 0.5f * (v + right), 0.5f * (v + up), 0.5f * (v + diagonal),
                                 0.5f * (right + up)}) {
        Ray down;
        down.origin = target + vec3(0.0f, 0.0f, 7.0f);
        down.direction = vec3(0.0f, 0.0f, -1.0f);
        rays.push_back(down);
        Ray oblique;
        oblique.origin = target + vec3(3.0f * u(rng), 3.0f * u(rng), 5.0f + u(rng));
        oblique.direction = target - oblique.origin;
        rays.push_back(oblique);
      }
    }
  }
  return rays;
}

Hit brute_force_closest(const TriangleMesh& mesh, const Ray& ray) {
  const WatertightRay wray = make_watertight_ray(ray.origin, ray.direction);
  Hit hit;
  float t_max = ray.t_max;
  for (uint32_t prim = 0; prim < mesh.triangle_count; ++prim) {
    TriangleHit tri_hit;
    if (!intersect_triangle(wray, mesh.triangle(prim), ray.t_min, t_max, tri_hit)) continue;
    if (hit.valid() && tri_hit.t >= hit.t) continue;
    t_max = tri_hit.t;
    hit = Hit{tri_hit.t, 0, prim, tri_hit.u, tri_hit.v};
  }
  return hit;
}

bool brute_force_any(const TriangleMesh& mesh, const Ray& ray) {
  const WatertightRay wray = make_watertight_ray(ray.origin, ray.direction);
  for (uint32_t prim = 0; prim < mesh.triangle_count; ++prim) {
    TriangleHit tri_hit;
    if (intersect_triangle(wray, mesh.triangle(prim), ray.t_min, ray.t_max, tri_hit)) return true;
  }
  return false;
}

::testing::AssertionResult same_closest_hit(const Hit& expected, const Hit& actual) {
  if (expected.valid() != actual.valid()) {
    return ::testing::AssertionFailure() << (expected.valid() ? "missed" : "hit") << " where brute force "
                                         << (expected.valid() ? "hits prim " : "misses, got prim ")
                                         << (expected.valid() ? expected.prim : actual.prim) << " at t "
                                         << (expected.valid() ? expected.t : actual.t);
  }
  if (!expected.valid()) return ::testing::AssertionSuccess();
  if (expected.t != actual.t) {
    return ::testing::AssertionFailure() << "t " << actual.t << " (prim " << actual.prim << ") instead of "
                                         << expected.t << " (prim " << expected.prim << ")";
  }
  const bool same_triangle = expected.prim == actual.prim && expected.instance == actual.instance;
  if (same_triangle && (expected.u != actual.u || expected.v != actual.v)) {
    return ::testing::AssertionFailure() << "prim " << actual.prim << " u, v " << actual.u << ", " << actual.v
                                         << " instead of " << expected.u << ", " << expected.v;
  }
  return ::testing::AssertionSuccess();
}

std::vector<Ray> make_axis_parallel_rays(const TestMesh& mesh, uint32_t seed, size_t count) {
  RayOptions options;
  options.axis_aligned_fraction = 0.6f;
  options.zero_component_fraction = 0.4f;
  std::vector<Ray> rays = make_random_rays(mesh, seed, count, options);
  for (size_t i = 0; i < rays.size(); i += 3) rays[i].origin = glm::round(rays[i].origin * 4.0f) * 0.25f;
  return rays;
}

StackedGrids make_stacked_grids(uint32_t cells, uint32_t flat_seed, uint32_t tilted_seed) {
  StackedGrids grids{make_grid(cells, false), {}};
  grids.rays = make_grid_edge_rays(grids.mesh, cells, flat_seed);
  const TestMesh tilted = make_grid(cells, true);
  const auto offset = static_cast<uint32_t>(grids.mesh.positions.size());
  for (const vec3& p : tilted.positions) grids.mesh.positions.push_back(p + vec3(0.0f, 0.0f, -40.0f));
  for (const uint32_t i : tilted.indices) grids.mesh.indices.push_back(i + offset);
  for (Ray ray : make_grid_edge_rays(tilted, cells, tilted_seed)) {
    ray.origin.z -= 40.0f;
    grids.rays.push_back(ray);
  }
  return grids;
}

BruteForceReference::BruteForceReference(TestMesh scene, std::vector<Ray> scene_rays)
    : mesh(std::move(scene)), rays(std::move(scene_rays)) {
  const TriangleMesh view = mesh.view();
  for (const Ray& ray : rays) {
    closest.push_back(brute_force_closest(view, ray));
    occluded.push_back(brute_force_any(view, ray) ? 1 : 0);
  }
}

}  // namespace glint::accel::testing
