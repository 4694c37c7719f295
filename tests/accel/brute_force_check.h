#pragma once
// One way to set up the accel tests that compare a structure's traversal with the brute force
// (test_scenes.h's BruteForceReference): the reference scenes, built once per test program, the
// comparison of every ray's closest and any hit, and the ray-interval check on three squares. The
// binary BVH (traversal_test.cpp) and the wide BVHs (wide/wide_bvh_traversal_test.cpp) use it; their
// suites run as one ctest each (tests/CMakeLists.txt), so the reference is made once, not per parameter.
#include "accel/test_scenes.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

namespace glint::accel::testing {

// The structure under test: the closest hit of every ray into hits, its occlusion into occluded.
using TraceClosestAndAny = std::function<void(std::span<const Ray> rays, std::span<Hit> hits,
                                              std::span<uint8_t> occluded)>;

// make(), the first time this call site asks; the same reference after (its brute force is the slow
// part, and every parameter of a suite compares with it). One static per lambda type, so one per
// call site.
template <typename Make>
const BruteForceReference& built_once(Make make) {
  static const BruteForceReference reference = make();
  return reference;
}

// make_random_soup(seed, triangles) and make_random_rays(soup, seed + 1, rays, options).
BruteForceReference make_soup_reference(uint32_t seed, uint32_t triangles, std::size_t rays,
                                        const RayOptions& options = {});
// make_clustered(seed, triangles) and make_random_rays(clusters, seed + 1, rays).
BruteForceReference make_clustered_reference(uint32_t seed, uint32_t triangles, std::size_t rays);
// make_stacked_grids(cells, seed, seed + 1): every ray hits.
BruteForceReference make_grids_reference(uint32_t cells, uint32_t seed);
// make_random_soup(seed, triangles) and make_axis_parallel_rays(soup, seed + 1, rays).
BruteForceReference make_axis_parallel_reference(uint32_t seed, uint32_t triangles, std::size_t rays);

struct BruteForceExpectations {
  bool every_ray_hits = false;     // watertight scenes: a miss slipped through
  double min_hit_fraction = 0.25;  // more rays than this share hit: the rays test something
};

// Traces reference.rays and expects the brute force's answers: the same closest hit
// (same_closest_hit), the same occlusion, any hit agreeing with closest hit, instance 0; stops
// after 10 rays that differ.
void expect_brute_force_answers(const BruteForceReference& reference, const TraceClosestAndAny& trace,
                                const BruteForceExpectations& expectations);

// Three parallel squares at z = 1, 2, 3 (two triangles each) for expect_ray_interval_honoured.
TestMesh make_three_squares();
// A ray down the z axis through make_three_squares() over several [t_min, t_max]: it hits exactly
// the squares inside, both ends inclusive, and any hit agrees with closest hit.
void expect_ray_interval_honoured(const TraceClosestAndAny& trace);

}  // namespace glint::accel::testing
