// The kd-tree (one SAH kd-tree per mesh under the TLAS) and `none` (one leaf per mesh: brute force)
// as structures of the cpu and cuda backends, through the RayTracer interface: closest hits and
// occlusion against brute force on the instanced scene and the reduced atrium, after deformation
// (a kd-tree update rebuilds), moved instances, and refit/auto refused with one clear error that
// changes nothing. The cuda instances need a CUDA GPU and skip without one.
#include "cuda/cuda_ray_tracer.h"
#include "cuda/device_query.h"
#include "rt/cpu_ray_tracer.h"
#include "rt/ray_tracer_check.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace glint::rt {
namespace {

using testing::brute_force_hits;
using testing::brute_force_occluded;
using testing::compare_hits;
using testing::compare_occluded;
using testing::random_rays;
using testing::trace;
using testing::trace_occluded;

AccelOptions with_structure(std::string_view name) {
  AccelOptions options;
  options.set_structure(parse_blas_structure(name));
  return options;
}

class KdTreeRayTracer : public ::testing::TestWithParam<const char*> {
protected:
  void SetUp() override {
    if (std::string(GetParam()) == "cuda" && !cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  }
  std::unique_ptr<RayTracer> make() const {
    if (std::string(GetParam()) == "cuda") return cuda::make_cuda_ray_tracer();
    return std::make_unique<CpuRayTracer>();
  }
  // Closest hits and occlusion of `tracer` equal brute force on `scene`.
  static void expect_brute_force(const RayTracer& tracer, const Scene& scene, size_t ray_count, uint32_t seed,
                                 const std::string& what) {
    const std::vector<accel::Ray> rays = random_rays(scene, ray_count, seed);
    EXPECT_EQ(compare_hits(scene, rays, brute_force_hits(scene, rays), trace(tracer, rays)), "") << what;
    const std::vector<accel::Ray> probes = testing::occlusion_test_rays(scene, ray_count / 2, seed + 1);
    EXPECT_EQ(compare_occluded(probes, brute_force_occluded(scene, probes), trace_occluded(tracer, probes)), "")
        << what;
  }
};

TEST_P(KdTreeRayTracer, KdTreeAndNoneEqualBruteForce) {
  for (const char* structure : {"kdtree", "none"}) {
    for (const Scene& scene : {testing::make_instanced_scene(), testing::make_reduced_atrium()}) {
      const auto tracer = make();
      tracer->build(scene, with_structure(structure));
      expect_brute_force(*tracer, scene, 2000, 11, structure);
      const RayTracerStats stats = tracer->stats();
      EXPECT_GT(stats.memory_bytes, 0u) << structure;
      EXPECT_EQ(stats.rebuilds + stats.refits, 0u);
    }
  }
}

TEST_P(KdTreeRayTracer, KdTreeUpdateRebuildsAndFollowsTheDeformation) {
  Scene scene = testing::make_instanced_scene();
  const auto tracer = make();
  tracer->build(scene, with_structure("kdtree"));
  SceneDeformers deformers(scene);
  for (int frame : {7, 19}) {
    const std::vector<accel::Ray> rays = random_rays(scene, 1500, static_cast<uint32_t>(frame));
    const std::vector<accel::Hit> before = brute_force_hits(scene, rays);
    const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
    ASSERT_FALSE(dirty.empty());
    tracer->update(scene, dirty, UpdatePolicy::rebuild);
    const std::vector<accel::Hit> after = brute_force_hits(scene, rays);
    ASSERT_NE(compare_hits(scene, rays, after, before), "") << "the deformation must change some hits";
    expect_brute_force(*tracer, scene, 1500, static_cast<uint32_t>(frame), "frame " + std::to_string(frame));
  }
  const RayTracerStats stats = tracer->stats();
  EXPECT_EQ(stats.rebuilds, 2 * scene.deformable_meshes().size());
  EXPECT_EQ(stats.refits, 0u);
  EXPECT_FALSE(stats.blas_sah_drift.has_value()) << "a kd-tree has no BVH SAH to drift";
}

TEST_P(KdTreeRayTracer, RefittingAKdTreeIsOneClearErrorThatChangesNothing) {
  Scene scene = testing::make_instanced_scene();
  const auto tracer = make();
  tracer->build(scene, with_structure("kdtree"));
  const std::vector<accel::Ray> rays = random_rays(scene, 1000, 3);
  const std::vector<accel::Hit> at_rest = trace(*tracer, rays);
  SceneDeformers deformers(scene);
  const std::vector<uint32_t> dirty = deformers.apply(scene, 9);
  for (UpdatePolicy policy : {UpdatePolicy::refit, UpdatePolicy::automatic}) {
    const std::string error = testing::error_of([&] { tracer->update(scene, dirty, policy); });
    EXPECT_NE(error.find("kdtree"), std::string::npos) << error;
    EXPECT_NE(error.find("cannot be refitted"), std::string::npos) << error;
    EXPECT_NE(error.find("use policy rebuild"), std::string::npos) << error;
    EXPECT_EQ(compare_hits(scene, rays, at_rest, trace(*tracer, rays)), "") << "a refused update changed the structure";
  }
  EXPECT_EQ(tracer->stats().rebuilds + tracer->stats().refits, 0u);
}

TEST_P(KdTreeRayTracer, KdTreeFollowsMovedInstancesWithAnyPolicy) {
  const Scene scene = testing::make_instanced_scene();
  for (UpdatePolicy policy : kAllUpdatePolicies) {
    const auto tracer = make();
    Scene moved = scene;
    tracer->build(moved, with_structure("kdtree"));
    moved.instances[5].transform[3] += vec4(0.5f, 1.0f, -0.25f, 0.0f);
    // No dirty mesh: only the TLAS follows, which every policy may refit.
    tracer->update(moved, {}, policy);
    expect_brute_force(*tracer, moved, 1000, 9, std::string(update_policy_name(policy)));
  }
}

INSTANTIATE_TEST_SUITE_P(Backend, KdTreeRayTracer, ::testing::Values("cpu", "cuda"),
                         [](const ::testing::TestParamInfo<const char*>& backend) { return std::string(backend.param); });

}  // namespace
}  // namespace glint::rt
