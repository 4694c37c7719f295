// accel-bench's optix rows: one GAS over the world triangles, hits with instance 0 and the world
// triangle index, equal to brute force; a refit follows moved vertices. Needs a build with OptiX and
// a CUDA GPU; skipped elsewhere.
#include "app/accel_bench/candidates_optix.h"

#include "accel/triangle_mesh.h"
#include "optix/test_support.h"
#include "rt/ray_tracer_check.h"

#include <gtest/gtest.h>

namespace glint::accel_bench {
namespace {

TEST(OptixCandidates, HitsEqualBruteForceAndRefitFollowsTheMesh) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  Scene flat = testing::flattened_single_mesh_scene(testing::make_instanced_scene());
  const std::vector<accel::Ray> rays = testing::random_rays(flat, 20000, 3);
  const std::vector<CandidateEntry> menu = optix_candidate_menu();
  ASSERT_EQ(menu.size(), optix_candidate_names().size());
  for (const CandidateEntry& entry : menu) {
    Scene scene = flat;
    Mesh& mesh = scene.meshes[0];
    Candidate candidate = entry.make();
    EXPECT_EQ(candidate.name, entry.name);
    EXPECT_GE(candidate.build(accel::make_indexed_mesh(mesh.positions, mesh.indices)), 0.0);
    std::vector<accel::Hit> hits(rays.size());
    candidate.trace_closest(rays, hits);
    EXPECT_EQ(testing::compare_hits_off_edges(scene, rays, testing::brute_force_hits(scene, rays), hits), "")
        << entry.name;
    EXPECT_GT(candidate.stats().memory_bytes, 0u);

    // Every vertex moved (a shear): the refitted GAS must find the moved triangles.
    for (vec3& p : mesh.positions) p += vec3(0.1f * p.y, 0.25f, -0.05f * p.x);
    const std::optional<double> refit_ms = candidate.refit(accel::make_indexed_mesh(mesh.positions, mesh.indices));
    ASSERT_TRUE(refit_ms.has_value()) << entry.name;
    EXPECT_GE(*refit_ms, 0.0);
    candidate.trace_closest(rays, hits);
    EXPECT_EQ(testing::compare_hits_off_edges(scene, rays, testing::brute_force_hits(scene, rays), hits), "")
        << entry.name << " after refit";
  }
}

}  // namespace
}  // namespace glint::accel_bench
