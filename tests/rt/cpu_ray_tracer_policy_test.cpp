// The cpu backend's update policies: the automatic rule (refit, rebuild past the SAH drift
// threshold), the SAH drift it reports, and refusing to refit a builder that cannot be refitted.
#include "rt/cpu_ray_tracer.h"

#include "rt/ray_tracer_check.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::rt {
namespace {

// Builds, deforms once, updates with `policy`, checks the hits and returns the stats. The policy
// and the drift come from the binary BVH whatever the traversal, so every check below runs with
// both traversals.
RayTracerStats update_once(Scene& scene, UpdatePolicy policy, float ratio, bool wide_traversal) {
  CpuRayTracer tracer;
  AccelOptions options;
  options.auto_rebuild_sah_ratio = ratio;
  options.wide_traversal = wide_traversal;
  tracer.build(scene, options);
  EXPECT_EQ(tracer.stats().blas_sah_drift, 1.0);
  SceneDeformers deformers(scene);
  tracer.update(scene, deformers.apply(scene, 13), policy);
  const std::vector<accel::Ray> rays = testing::random_rays(scene, 1000, 21);
  EXPECT_EQ(testing::compare_hits(scene, rays, testing::brute_force_hits(scene, rays), testing::trace(tracer, rays)), "");
  return tracer.stats();
}

class CpuRayTracerPolicy : public ::testing::TestWithParam<bool> {};

TEST_P(CpuRayTracerPolicy, RefitDriftsAndRebuildDoesNot) {
  Scene refitted = testing::make_strongly_deforming_scene();
  const RayTracerStats refit = update_once(refitted, UpdatePolicy::refit, 1.3f, GetParam());
  EXPECT_EQ(refit.refits, 1u);
  EXPECT_EQ(refit.rebuilds, 0u);
  ASSERT_TRUE(refit.blas_sah_drift.has_value());
  EXPECT_GT(*refit.blas_sah_drift, 1.0);

  Scene rebuilt = testing::make_strongly_deforming_scene();
  const RayTracerStats rebuild = update_once(rebuilt, UpdatePolicy::rebuild, 1.3f, GetParam());
  EXPECT_EQ(rebuild.rebuilds, 1u);
  EXPECT_EQ(rebuild.refits, 0u);
  EXPECT_EQ(rebuild.blas_sah_drift, 1.0);
}

TEST_P(CpuRayTracerPolicy, AutomaticRebuildsPastTheThresholdAndRefitsBelowIt) {
  Scene strict = testing::make_strongly_deforming_scene();
  const RayTracerStats rebuilt = update_once(strict, UpdatePolicy::automatic, 1.0f, GetParam());
  EXPECT_EQ(rebuilt.rebuilds, 1u);
  EXPECT_EQ(rebuilt.refits, 0u);
  EXPECT_EQ(rebuilt.blas_sah_drift, 1.0);

  Scene lenient = testing::make_strongly_deforming_scene();
  const RayTracerStats refitted = update_once(lenient, UpdatePolicy::automatic, 1000.0f, GetParam());
  EXPECT_EQ(refitted.rebuilds, 0u);
  EXPECT_EQ(refitted.refits, 1u);
  ASSERT_TRUE(refitted.blas_sah_drift.has_value());
  EXPECT_GT(*refitted.blas_sah_drift, 1.0);
}

TEST(CpuRayTracerPolicyOptions, NoDriftWithoutDeformableMeshes) {
  Scene scene = testing::make_instanced_scene();
  for (Mesh& mesh : scene.meshes) {
    mesh.deformable = false;
    mesh.deform.reset();
  }
  CpuRayTracer tracer;
  tracer.build(scene, {});
  EXPECT_FALSE(tracer.stats().blas_sah_drift.has_value());
}

TEST_P(CpuRayTracerPolicy, RefittingSbvhIsAClearErrorAndRebuildingWorks) {
  Scene scene = testing::make_instanced_scene();
  CpuRayTracer tracer;
  AccelOptions options;
  options.builder = accel::BvhBuilder::sbvh;
  options.wide_traversal = GetParam();
  tracer.build(scene, options);
  SceneDeformers deformers(scene);
  const std::vector<uint32_t> dirty = deformers.apply(scene, 9);
  for (UpdatePolicy policy : {UpdatePolicy::refit, UpdatePolicy::automatic}) {
    const std::string error = testing::error_of([&] { tracer.update(scene, dirty, policy); });
    EXPECT_NE(error.find("sbvh"), std::string::npos) << error;
    EXPECT_NE(error.find("cannot be refitted"), std::string::npos) << error;
  }
  tracer.update(scene, dirty, UpdatePolicy::rebuild);
  const std::vector<accel::Ray> rays = testing::random_rays(scene, 1000, 4);
  EXPECT_EQ(testing::compare_hits(scene, rays, testing::brute_force_hits(scene, rays), testing::trace(tracer, rays)), "");
}

INSTANTIATE_TEST_SUITE_P(Traversal, CpuRayTracerPolicy, ::testing::Values(true, false),
                         [](const ::testing::TestParamInfo<bool>& traversal) { return traversal.param ? "wide" : "binary"; });

TEST(CpuRayTracerPolicyOptions, ThresholdBelowOneIsRefused) {
  CpuRayTracer tracer;
  AccelOptions options;
  options.auto_rebuild_sah_ratio = 0.5f;
  const std::string error = testing::error_of([&] { tracer.build(testing::make_instanced_scene(), options); });
  EXPECT_NE(error.find("auto_rebuild_sah_ratio"), std::string::npos) << error;
}

}  // namespace
}  // namespace glint::rt
