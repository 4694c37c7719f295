// InstanceSubsetTracer (glint bench's Fig. 10): rays see exactly the chosen instances, before and
// after the deformable meshes moved, and hits name the full scene's instances.
#include "rt/instance_subset_tracer.h"
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

// Brute-force hits against only `instances` of `scene`, renumbered to the full scene's instances.
std::vector<accel::Hit> subset_reference(const Scene& scene, const std::vector<std::uint32_t>& instances,
                                         std::span<const accel::Ray> rays) {
  Scene only = scene;
  only.instances.clear();
  for (const std::uint32_t instance : instances) only.instances.push_back(scene.instances[instance]);
  std::vector<accel::Hit> hits = brute_force_hits(only, rays);
  for (accel::Hit& hit : hits)
    if (hit.valid()) hit.instance = instances[hit.instance];
  return hits;
}

TEST(InstanceSubsetTracer, DeformableInstancesAreTheSheets) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<std::uint32_t> instances = deformable_instances(scene);
  ASSERT_FALSE(instances.empty());
  for (std::uint32_t i = 0; i < scene.instances.size(); ++i) {
    const bool listed = std::find(instances.begin(), instances.end(), i) != instances.end();
    EXPECT_EQ(listed, scene.meshes[scene.instances[i].mesh].deformable) << "instance " << i;
  }
}

TEST(InstanceSubsetTracer, SeesOnlyTheChosenInstancesBeforeAndAfterDeforming) {
  for (const std::string_view backend : {"cpu", "embree"}) {
    for (const UpdatePolicy policy : {UpdatePolicy::rebuild, UpdatePolicy::refit}) {
      Scene scene = testing::make_instanced_scene();
      const std::vector<std::uint32_t> instances = deformable_instances(scene);
      InstanceSubsetTracer tracer(backends::make_ray_tracer(backend), instances);
      tracer.build(scene, {});
      EXPECT_EQ(tracer.name(), backend);
      EXPECT_EQ(tracer.subset_scene().instances.size(), instances.size());

      const std::vector<accel::Ray> rays = random_rays(scene, 3000, 11);
      const std::vector<accel::Hit> full = brute_force_hits(scene, rays);
      const std::vector<accel::Hit> expected = subset_reference(scene, instances, rays);
      std::size_t hidden_hits = 0;  // rays whose full-scene hit is on an instance the subset ignores
      for (std::size_t i = 0; i < rays.size(); ++i)
        hidden_hits += full[i].valid() && !(expected[i].valid() && expected[i].instance == full[i].instance) ? 1 : 0;
      ASSERT_GT(hidden_hits, rays.size() / 10) << "the test needs rays that the ignored instances would stop";
      EXPECT_EQ(compare_hits(scene, rays, expected, trace(tracer, rays)), "") << backend;

      SceneDeformers deformers(scene);
      tracer.update(scene, deformers.apply(scene, 40), policy);
      EXPECT_EQ(compare_hits(scene, rays, subset_reference(scene, instances, rays), trace(tracer, rays)), "")
          << backend << " after " << update_policy_name(policy);
    }
  }
}

TEST(InstanceSubsetTracer, KeepsTheChosenOrderWhenRenumberingHits) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<std::uint32_t> instances = {3, 0};  // a sheet, then the floor: not ascending
  InstanceSubsetTracer tracer(backends::make_ray_tracer("cpu"), instances);
  tracer.build(scene, {});
  const std::vector<accel::Ray> rays = random_rays(scene, 2000, 5);
  EXPECT_EQ(compare_hits(scene, rays, subset_reference(scene, instances, rays), trace(tracer, rays)), "");
}

TEST(InstanceSubsetTracer, RejectsEmptyRepeatedAndOutOfRangeInstances) {
  EXPECT_NE(testing::error_of([] { InstanceSubsetTracer(backends::make_ray_tracer("cpu"), {}); }).find("no instances"),
            std::string::npos);
  EXPECT_NE(testing::error_of([] { InstanceSubsetTracer(backends::make_ray_tracer("cpu"), {1, 2, 1}); }).find("instance 1 is listed twice"),
            std::string::npos);
  const Scene scene = testing::make_instanced_scene();
  InstanceSubsetTracer tracer(backends::make_ray_tracer("cpu"), {0, 99});
  EXPECT_NE(testing::error_of([&] { tracer.build(scene, {}); }).find("instance 99 out of range"), std::string::npos);
}

}  // namespace
}  // namespace glint::rt
