#include "accel/brute_force_check.h"

#include <utility>
#include <vector>

namespace glint::accel::testing {

BruteForceReference make_soup_reference(uint32_t seed, uint32_t triangles, std::size_t rays,
                                        const RayOptions& options) {
  TestMesh soup = make_random_soup(seed, triangles);
  std::vector<Ray> soup_rays = make_random_rays(soup, seed + 1, rays, options);
  return BruteForceReference(std::move(soup), std::move(soup_rays));
}

BruteForceReference make_clustered_reference(uint32_t seed, uint32_t triangles, std::size_t rays) {
  TestMesh clustered = make_clustered(seed, triangles);
  std::vector<Ray> cluster_rays = make_random_rays(clustered, seed + 1, rays);
  return BruteForceReference(std::move(clustered), std::move(cluster_rays));
}

BruteForceReference make_grids_reference(uint32_t cells, uint32_t seed) {
  StackedGrids grids = make_stacked_grids(cells, seed, seed + 1);
  return BruteForceReference(std::move(grids.mesh), std::move(grids.rays));
}

BruteForceReference make_axis_parallel_reference(uint32_t seed, uint32_t triangles, std::size_t rays) {
  TestMesh soup = make_random_soup(seed, triangles);
  std::vector<Ray> axis_rays = make_axis_parallel_rays(soup, seed + 1, rays);
  return BruteForceReference(std::move(soup), std::move(axis_rays));
}

void expect_brute_force_answers(const BruteForceReference& reference, const TraceClosestAndAny& trace,
                                const BruteForceExpectations& expectations) {
  std::vector<Hit> hits(reference.rays.size());
  std::vector<uint8_t> occluded(reference.rays.size());
  trace(reference.rays, hits, occluded);
  std::size_t failures = 0, hit_count = 0;
  for (std::size_t i = 0; i < reference.rays.size() && failures < 10; ++i) {
    const ::testing::AssertionResult same = same_closest_hit(reference.closest[i], hits[i]);
    EXPECT_TRUE(same) << "ray " << i;
    EXPECT_EQ(occluded[i], reference.occluded[i]) << "ray " << i;
    EXPECT_EQ(reference.occluded[i] != 0, reference.closest[i].valid()) << "ray " << i;
    EXPECT_EQ(occluded[i] != 0, hits[i].valid()) << "ray " << i << ": any hit disagrees with closest hit";
    if (hits[i].valid()) {
      EXPECT_EQ(hits[i].instance, 0u) << "ray " << i;
    }
    if (expectations.every_ray_hits) {
      EXPECT_TRUE(hits[i].valid()) << "ray " << i << " slipped through";
    }
    failures += same && occluded[i] == reference.occluded[i] ? 0 : 1;
    hit_count += hits[i].valid() ? 1 : 0;
  }
  EXPECT_GT(static_cast<double>(hit_count), expectations.min_hit_fraction * static_cast<double>(reference.rays.size()));
}

TestMesh make_three_squares() {
  TestMesh mesh;
  for (float z : {1.0f, 2.0f, 3.0f}) {
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, -1, z), vec3(1, 1, z));
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, 1, z), vec3(-1, 1, z));
  }
  return mesh;
}

void expect_ray_interval_honoured(const TraceClosestAndAny& trace) {
  const auto closest_t = [&](float t_min, float t_max) {
    const Ray ray{vec3(0.25f, 0.5f, 0.0f), t_min, vec3(0, 0, 1), t_max};
    Hit hit;
    uint8_t occluded = 0;
    trace(std::span(&ray, 1), std::span(&hit, 1), std::span(&occluded, 1));
    EXPECT_EQ(occluded != 0, hit.valid()) << "[" << t_min << ", " << t_max << "]";
    return hit.valid() ? hit.t : -1.0f;
  };
  EXPECT_EQ(closest_t(0.0f, kInfinity), 1.0f);
  EXPECT_EQ(closest_t(1.5f, kInfinity), 2.0f);
  EXPECT_EQ(closest_t(2.0f, kInfinity), 2.0f);  // t_min inclusive
  EXPECT_EQ(closest_t(2.5f, 2.9f), -1.0f);
  EXPECT_EQ(closest_t(2.5f, 3.0f), 3.0f);       // t_max inclusive
  EXPECT_EQ(closest_t(3.5f, kInfinity), -1.0f);
  EXPECT_EQ(closest_t(0.0f, 0.5f), -1.0f);
}

}  // namespace glint::accel::testing
