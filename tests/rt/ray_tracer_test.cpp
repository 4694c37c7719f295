// Both RayTracer backends against brute force over the flattened world triangles, before and after
// the deformable meshes moved, for every update policy, and against each other.
#include "rt/ray_tracer.h"
#include "backends/registry.h"

#include "rt/ray_tracer_check.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::rt {
namespace {

using testing::brute_force_hits;
using testing::compare_hits;
using testing::random_rays;
using testing::trace;

constexpr std::string_view kBackends[] = {"cpu", "embree"};

TEST(RayTracer, BackendsEqualBruteForceOnAnInstancedScene) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = random_rays(scene, 3000, 7);
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  size_t hit_count = 0;
  for (const accel::Hit& hit : expected) hit_count += hit.valid() ? 1 : 0;
  ASSERT_GT(hit_count, rays.size() / 4) << "the rays must mostly hit something to test anything";
  for (std::string_view backend : kBackends) {
    const auto tracer = backends::make_ray_tracer(backend);
    EXPECT_EQ(tracer->name(), backend);
    tracer->build(scene, {});
    EXPECT_EQ(compare_hits(scene, rays, expected, trace(*tracer, rays)), "") << backend;
    const RayTracerStats stats = tracer->stats();
    EXPECT_EQ(stats.backend, backend);
    EXPECT_GT(stats.memory_bytes, 0u);
    EXPECT_EQ(stats.rebuilds + stats.refits, 0u);
  }
}

TEST(RayTracer, CpuBackendEqualsBruteForceWithEveryBuilder) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = random_rays(scene, 1000, 11);
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    for (bool wide : {true, false}) {
      const auto tracer = backends::make_ray_tracer("cpu");
      AccelOptions options;
      options.builder = builder;
      options.wide_traversal = wide;
      tracer->build(scene, options);
      EXPECT_EQ(compare_hits(scene, rays, expected, trace(*tracer, rays)), "")
          << accel::builder_name(builder) << (wide ? " wide" : " binary");
    }
  }
}

TEST(RayTracer, BackendsEqualBruteForceAndEachOtherOnReducedAtrium) {
  const Scene scene = testing::make_reduced_atrium();
  ASSERT_FALSE(scene.deformable_meshes().empty());
  const std::vector<accel::Ray> rays = random_rays(scene, 400, 3);
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  std::vector<std::vector<accel::Hit>> per_backend;
  for (std::string_view backend : kBackends) {
    const auto tracer = backends::make_ray_tracer(backend);
    tracer->build(scene, {});
    per_backend.push_back(trace(*tracer, rays));
    EXPECT_EQ(compare_hits(scene, rays, expected, per_backend.back()), "") << backend;
  }
  EXPECT_EQ(compare_hits(scene, rays, per_backend[0], per_backend[1]), "") << "cpu vs embree";
}

// Deforms, updates with `policy` and checks against brute force on the deformed geometry, twice
// (two frames), so a second update on top of a refit is covered too.
void check_updates(Scene scene, std::string_view backend, UpdatePolicy policy, size_t ray_count,
                   const AccelOptions& options = {}) {
  const auto tracer = backends::make_ray_tracer(backend);
  tracer->build(scene, options);
  SceneDeformers deformers(scene);
  const std::vector<accel::Ray> rays = random_rays(scene, ray_count, 5);
  const std::vector<accel::Hit> rest = brute_force_hits(scene, rays);
  for (int frame : {17, 40}) {
    const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
    ASSERT_FALSE(dirty.empty());
    tracer->update(scene, dirty, policy);
    const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
    ASSERT_NE(compare_hits(scene, rays, rest, expected), "") << "the deformation must change some hits";
    EXPECT_EQ(compare_hits(scene, rays, expected, trace(*tracer, rays)), "")
        << backend << " " << update_policy_name(policy) << " frame " << frame
        << (options.wide_traversal ? "" : " binary traversal");
  }
  const RayTracerStats stats = tracer->stats();
  EXPECT_EQ(stats.rebuilds + stats.refits, 2 * scene.deformable_meshes().size());
  if (policy == UpdatePolicy::rebuild) {
    EXPECT_EQ(stats.refits, 0u);
  }
  if (policy == UpdatePolicy::refit) {
    EXPECT_EQ(stats.rebuilds, 0u);
  }
}

TEST(RayTracer, UpdatesEqualBruteForceOnTheDeformedInstancedScene) {
  for (std::string_view backend : kBackends)
    for (UpdatePolicy policy : kAllUpdatePolicies) check_updates(testing::make_instanced_scene(), backend, policy, 1500);
  AccelOptions binary;  // the cpu backend's binary traversal (the wide one is the default above)
  binary.wide_traversal = false;
  for (UpdatePolicy policy : kAllUpdatePolicies)
    check_updates(testing::make_instanced_scene(), "cpu", policy, 1500, binary);
}

TEST(RayTracer, UpdatesEqualBruteForceOnTheDeformedReducedAtrium) {
  const Scene scene = testing::make_reduced_atrium();
  for (std::string_view backend : kBackends)
    for (UpdatePolicy policy : kAllUpdatePolicies) check_updates(scene, backend, policy, 200);
  AccelOptions binary;
  binary.wide_traversal = false;
  for (UpdatePolicy policy : kAllUpdatePolicies) check_updates(scene, "cpu", policy, 200, binary);
}

TEST(RayTracer, UpdateFollowsMovedInstances) {
  Scene scene = testing::make_instanced_scene();
  for (const auto& [backend, wide] : {std::pair{"cpu", true}, std::pair{"cpu", false}, std::pair{"embree", true}}) {
    Scene moved = scene;
    const auto tracer = backends::make_ray_tracer(backend);
    AccelOptions options;
    options.wide_traversal = wide;
    tracer->build(moved, options);
    moved.instances[5].transform[3] += vec4(0.5f, 1.0f, -0.25f, 0.0f);
    tracer->update(moved, {}, UpdatePolicy::refit);
    const std::vector<accel::Ray> rays = random_rays(moved, 1000, 9);
    EXPECT_EQ(compare_hits(moved, rays, brute_force_hits(moved, rays), trace(*tracer, rays)), "")
        << backend << (wide ? "" : " binary traversal");
  }
}

TEST(RayTracer, NamesRoundTripAndUnknownNamesAreClearErrors) {
  for (UpdatePolicy policy : kAllUpdatePolicies) EXPECT_EQ(parse_update_policy(update_policy_name(policy)), policy);
  EXPECT_EQ(update_policy_name(UpdatePolicy::automatic), "auto");
  const std::string policy_error = testing::error_of([] { (void)parse_update_policy("sometimes"); });
  EXPECT_NE(policy_error.find("unknown update policy \"sometimes\""), std::string::npos) << policy_error;
  EXPECT_NE(policy_error.find("rebuild, refit, auto"), std::string::npos) << policy_error;
  const std::string backend_error = testing::error_of([] { (void)backends::make_ray_tracer("vulkan"); });
  EXPECT_NE(backend_error.find("\"vulkan\""), std::string::npos) << backend_error;
  EXPECT_NE(backend_error.find("cpu, embree"), std::string::npos) << backend_error;
}

TEST(RayTracer, MisuseIsAClearError) {
  Scene scene = testing::make_instanced_scene();
  for (std::string_view backend : kBackends) {
    const auto tracer = backends::make_ray_tracer(backend);
    std::vector<accel::Ray> rays(3);
    std::vector<accel::Hit> hits(3);
    EXPECT_NE(testing::error_of([&] { tracer->trace_closest(rays, hits); }).find("before build()"), std::string::npos);
    EXPECT_NE(testing::error_of([&] { tracer->update(scene, {}, UpdatePolicy::refit); }).find("before build()"),
              std::string::npos);
    tracer->build(scene, {});
    std::vector<accel::Hit> too_few(2);
    (void)testing::error_of([&] { tracer->trace_closest(rays, too_few); });
    const std::vector<uint32_t> out_of_range{99};
    EXPECT_NE(testing::error_of([&] { tracer->update(scene, out_of_range, UpdatePolicy::refit); })
                  .find("dirty mesh index 99"),
              std::string::npos);
    Scene grown = scene;
    grown.meshes[2].positions.push_back(vec3(0.0f));
    grown.meshes[2].normals.push_back(vec3(0, 0, 1));
    const std::vector<uint32_t> sheet{2};
    EXPECT_NE(testing::error_of([&] { tracer->update(grown, sheet, UpdatePolicy::rebuild); }).find("build() again"),
              std::string::npos);
  }
}

}  // namespace
}  // namespace glint::rt
