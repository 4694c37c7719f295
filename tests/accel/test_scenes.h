#pragma once
// Scenes, rays and the brute-force reference shared by the accel tests.
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace glint::accel::testing {

// Owns indexed triangles; view() is valid while the TestMesh lives and is not resized.
struct TestMesh {
  std::vector<vec3> positions;
  std::vector<uint32_t> indices;

  uint32_t add_vertex(const vec3& p);
  void add_triangle(const vec3& a, const vec3& b, const vec3& c);
  void add_triangle(uint32_t a, uint32_t b, uint32_t c);
  uint32_t triangle_count() const { return static_cast<uint32_t>(indices.size() / 3); }
  TriangleMesh view() const { return make_indexed_mesh(positions, indices); }
  Aabb bounds() const;
};

// Many small triangles, a few huge ones crossing everything, axis-aligned ones (some coplanar and
// overlapping), exact duplicates (shared indices, copied vertices, flipped winding).
TestMesh make_random_soup(uint32_t seed, uint32_t triangle_count);

// A (cells x cells) grid of quads split into two triangles each, vertices at integer x, y in the
// plane z = 0, or on a tilted plane when `tilted`. Every interior edge and vertex is shared.
TestMesh make_grid(uint32_t cells, bool tilted);

// Gaussian clusters of very different sizes: where SAH and the median split disagree most.
TestMesh make_clustered(uint32_t seed, uint32_t triangle_count);

// The cases that break careless builders: zero-area triangles (repeated vertices, collinear
// corners), coplanar overlapping triangles on one plane, exact duplicates, huge (1e3) and tiny (1e-5)
// triangles among unit-sized ones, and a subset (about a tenth) whose boxes all share one exact
// centre, so their centroids coincide bit for bit.
TestMesh make_degenerate_soup(uint32_t seed, uint32_t triangle_count);

struct RayOptions {
  float axis_aligned_fraction = 0.1f;   // direction along +-x, +-y or +-z exactly
  float zero_component_fraction = 0.1f; // one direction component exactly 0
  float limited_fraction = 0.2f;        // random [t_min, t_max] instead of [0, inf)
  float aimed_fraction = 0.5f;          // aimed at a random point of a random triangle
};

// Origins in the mesh's box grown by half its size.
std::vector<Ray> make_random_rays(const TestMesh& mesh, uint32_t seed, size_t count, const RayOptions& options = {});

// Rays from above the grid aimed exactly at interior vertices, edge midpoints and diagonal
// midpoints, half of them straight down (-z) and half oblique. All of them must hit.
std::vector<Ray> make_grid_edge_rays(const TestMesh& grid, uint32_t cells, uint32_t seed);

// Reference: every triangle, in index order, keeping the first of equal t.
Hit brute_force_closest(const TriangleMesh& mesh, const Ray& ray);
bool brute_force_any(const TriangleMesh& mesh, const Ray& ray);

// Exact agreement: same miss/hit, bit-identical t (both run the same triangle test on the same
// ray); same (instance, prim) => identical u, v; another triangle at the same t is a tie (shared
// edge, duplicate) and accepted.
::testing::AssertionResult same_closest_hit(const Hit& expected, const Hit& actual);

// Random rays of which 60 % are axis-parallel and 40 % have zero direction components, every third
// starting exactly on a multiple of 0.25 (the planes of axis-aligned triangles and their boxes).
std::vector<Ray> make_axis_parallel_rays(const TestMesh& mesh, uint32_t seed, size_t count);

// A flat grid with a tilted grid 40 units below it in one mesh, and edge/vertex rays of both
// (make_grid_edge_rays, the tilted grid's moved down with it): the tilted grid is reached only
// through holes, i.e. never, unless the flat grid leaks. Every ray hits.
struct StackedGrids {
  TestMesh mesh;
  std::vector<Ray> rays;
};
StackedGrids make_stacked_grids(uint32_t cells, uint32_t flat_seed, uint32_t tilted_seed);

// A scene, its rays and the brute-force answers (closest hit, occlusion), computed once so that
// every structure under test is compared with the same answers.
struct BruteForceReference {
  TestMesh mesh;
  std::vector<Ray> rays;
  std::vector<Hit> closest;
  std::vector<uint8_t> occluded;

  BruteForceReference(TestMesh scene, std::vector<Ray> scene_rays);
};

}  // namespace glint::accel::testing
