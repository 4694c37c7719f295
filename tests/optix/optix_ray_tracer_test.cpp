// The optix backend against brute force and the cpu backend, before and after deformation, through
// the host and the device-resident paths. Needs a build with OptiX and a CUDA GPU; skipped elsewhere
// (the GPU machine runs them: --gtest_filter='Optix*').
#include "rt/ray_tracer.h"
#include "backends/registry.h"
#include "optix/build_preference.h"

#include "optix/test_support.h"
#include "rt/ray_tracer_check.h"
#include "rt/reflection_rays.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#if GLINT_HAVE_OPTIX
#include "cuda/device_buffer.h"

#include <cuda_runtime.h>
#endif

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cstring>

namespace glint::rt {
namespace {

using testing::brute_force_hits;
using testing::compare_hits;
using testing::compare_hits_off_edges;
using testing::random_rays;
using testing::reflection_like_rays;
using testing::trace;

AccelOptions optix_options(optix::BuildPreference preference) {
  AccelOptions options;
  options.backend_structure = optix::kBuildPreferenceNames.name_of(preference);
  return options;
}

std::size_t hit_count(std::span<const accel::Hit> hits) {
  std::size_t count = 0;
  for (const accel::Hit& hit : hits) count += hit.valid() ? 1 : 0;
  return count;
}

std::vector<accel::Hit> cpu_hits(const Scene& scene, std::span<const accel::Ray> rays) {
  const auto cpu = backends::make_ray_tracer("cpu");
  cpu->build(scene, {});
  return trace(*cpu, rays);
}

TEST(OptixRayTracer, HitsEqualBruteForceOnTheInstancedScene) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = random_rays(scene, 20000, 7);
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  ASSERT_GT(hit_count(expected), rays.size() / 4) << "the rays must mostly hit something to test anything";
  for (const optix::BuildPreference preference : optix::kAllBuildPreferences) {
    const auto tracer = backends::make_ray_tracer("optix");
    EXPECT_EQ(tracer->name(), "optix");
    ASSERT_NE(tracer->device_tracing(), nullptr);
    tracer->build(scene, optix_options(preference));
    EXPECT_EQ(compare_hits_off_edges(scene, rays, expected, trace(*tracer, rays)), "") << optix::kBuildPreferenceNames.name_of(preference);
    const RayTracerStats stats = tracer->stats();
    EXPECT_EQ(stats.backend, "optix");
    EXPECT_GT(stats.memory_bytes, 0u);
    EXPECT_GT(stats.build_ms, 0.0);
    EXPECT_EQ(stats.rebuilds + stats.refits, 0u);
    EXPECT_FALSE(stats.blas_sah_drift.has_value());
  }
}

TEST(OptixRayTracer, HitsEqualTheCpuBackendOnReducedAtriumReflectionRays) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_reduced_atrium();
  std::vector<accel::Ray> rays = reflection_like_rays(scene, 100000, 21);
  const std::vector<accel::Ray> random = random_rays(scene, 20000, 22);
  rays.insert(rays.end(), random.begin(), random.end());
  const std::vector<accel::Hit> expected = cpu_hits(scene, rays);
  ASSERT_GT(hit_count(expected), rays.size() / 4);
  for (const optix::BuildPreference preference : optix::kAllBuildPreferences) {
    const auto tracer = backends::make_ray_tracer("optix");
    tracer->build(scene, optix_options(preference));
    EXPECT_EQ(compare_hits_off_edges(scene, rays, expected, trace(*tracer, rays)), "") << optix::kBuildPreferenceNames.name_of(preference);
  }
}

// Built at rest, then two frames of deformation: every policy's hits equal the cpu backend's on the
// deformed scene, and the updated (refit) GASes' hits equal the rebuilt ones'.
TEST(OptixRayTracer, UpdatedGasHitsEqualRebuiltGasHitsAfterDeformation) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  Scene scene = testing::make_reduced_atrium();
  const std::size_t deformable = scene.deformable_meshes().size();
  ASSERT_GT(deformable, 0u);
  SceneDeformers deformers(scene);
  const std::vector<accel::Ray> rays = random_rays(scene, 100000, 5);
  const std::vector<accel::Hit> rest = cpu_hits(scene, rays);
  for (const optix::BuildPreference preference : optix::kAllBuildPreferences) {
    Scene posed = scene;
    std::vector<std::unique_ptr<RayTracer>> tracers;
    for (std::size_t p = 0; p < std::size(kAllUpdatePolicies); ++p) {
      tracers.push_back(backends::make_ray_tracer("optix"));
      tracers.back()->build(posed, optix_options(preference));
    }
    for (const int frame : {17, 40}) {
      const std::vector<uint32_t> dirty = deformers.apply(posed, frame);
      ASSERT_FALSE(dirty.empty());
      const std::vector<accel::Hit> expected = cpu_hits(posed, rays);
      ASSERT_NE(compare_hits(posed, rays, rest, expected), "") << "the deformation must change some hits";
      std::vector<std::vector<accel::Hit>> per_policy;
      for (std::size_t p = 0; p < tracers.size(); ++p) {
        tracers[p]->update(posed, dirty, kAllUpdatePolicies[p]);
        per_policy.push_back(trace(*tracers[p], rays));
        EXPECT_EQ(compare_hits_off_edges(posed, rays, expected, per_policy.back()), "")
            << optix::kBuildPreferenceNames.name_of(preference) << " " << update_policy_name(kAllUpdatePolicies[p]) << " frame " << frame;
      }
      static_assert(kAllUpdatePolicies[0] == UpdatePolicy::rebuild && kAllUpdatePolicies[1] == UpdatePolicy::refit);
      EXPECT_EQ(compare_hits_off_edges(posed, rays, per_policy[0], per_policy[1]), "")
          << optix::kBuildPreferenceNames.name_of(preference) << ": refitted vs rebuilt GASes, frame " << frame;
    }
    for (std::size_t p = 0; p < tracers.size(); ++p) {
      const RayTracerStats stats = tracers[p]->stats();
      EXPECT_EQ(stats.rebuilds + stats.refits, 2 * deformable) << update_policy_name(kAllUpdatePolicies[p]);
      EXPECT_GT(stats.last_update_ms, 0.0);
      if (kAllUpdatePolicies[p] == UpdatePolicy::rebuild) {
        EXPECT_EQ(stats.refits, 0u);
      } else {
        EXPECT_EQ(stats.rebuilds, 0u) << "deformable GASes are built updatable: refit and auto never rebuild";
      }
    }
  }
}

TEST(OptixRayTracer, UpdateFollowsMovedInstances) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("optix");
  tracer->build(scene, {});
  scene.instances[2].transform = glm::translate(scene.instances[2].transform, vec3(0.5f, -0.25f, 1.0f));
  scene.instances[0].transform = glm::translate(scene.instances[0].transform, vec3(0.0f, 0.3f, 0.0f));
  tracer->update(scene, {}, UpdatePolicy::refit);
  const std::vector<accel::Ray> rays = random_rays(scene, 20000, 9);
  EXPECT_EQ(compare_hits_off_edges(scene, rays, brute_force_hits(scene, rays), trace(*tracer, rays)), "");
}

TEST(OptixRayTracer, MisuseIsAClearError) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("optix");
  std::vector<accel::Hit> hits(1);
  const std::vector<accel::Ray> rays(1);
  EXPECT_NE(testing::error_of([&] { tracer->trace_closest(rays, hits); }).find("before build()"), std::string::npos);
  tracer->build(scene, {});
  hits.resize(2);
  EXPECT_NE(testing::error_of([&] { tracer->trace_closest(rays, hits); }).find("1 rays but 2 hit records"),
            std::string::npos);
  const auto mesh_count = static_cast<uint32_t>(scene.meshes.size());
  const std::vector<uint32_t> out_of_range{mesh_count};
  EXPECT_NE(testing::error_of([&] { tracer->device_tracing()->device_positions(mesh_count); })
                .find("device_positions of mesh"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { tracer->update(scene, out_of_range, UpdatePolicy::refit); }).find("optix"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { tracer->device_tracing()->update_device(out_of_range, UpdatePolicy::refit); })
                .find("dirty mesh"),
            std::string::npos);
}

#if GLINT_HAVE_OPTIX

// The renderer's path: rays and hits in device memory, the ray count read on the GPU. Slots past
// the count are left untouched; the traced ones equal the host path's hits bit for bit.
TEST(OptixRayTracer, DeviceTraceStopsAtTheGpuSideRayCount) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("optix");
  tracer->build(scene, {});
  DeviceTracing& device = *tracer->device_tracing();
  const std::vector<accel::Ray> rays = random_rays(scene, 5000, 13);
  const std::vector<accel::Hit> host = trace(*tracer, rays);
  const auto traced = static_cast<uint32_t>(rays.size() / 2 + 7);
  cuda::DeviceBuffer<accel::Ray> device_rays;
  device_rays.upload(rays);
  cuda::DeviceBuffer<accel::Hit> device_hits(rays.size());
  ASSERT_EQ(cudaMemset(device_hits.data(), 0xAB, device_hits.bytes()), cudaSuccess);
  cuda::DeviceBuffer<uint32_t> count;
  count.upload(std::span<const uint32_t>(&traced, 1));
  GpuTicket last = 0;
  for (int repeat = 0; repeat < 2; ++repeat)  // the second launch reuses the uploaded parameters
    last = device.trace_closest_device(device_rays.data(), device_hits.data(), count.data(),
                                       static_cast<uint32_t>(rays.size()));
  ASSERT_EQ(cudaStreamSynchronize(static_cast<cudaStream_t>(device.stream())), cudaSuccess);
  EXPECT_GE(*device.gpu_ms(last, /*wait=*/true), 0.0);
  const std::vector<accel::Hit> hits = device_hits.download();
  unsigned char untouched[sizeof(accel::Hit)];
  std::memset(untouched, 0xAB, sizeof(untouched));
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (i < traced) {
      ASSERT_EQ(std::memcmp(&hits[i], &host[i], sizeof(accel::Hit)), 0) << "ray " << i;
    } else {
      ASSERT_EQ(std::memcmp(&hits[i], untouched, sizeof(accel::Hit)), 0) << "slot " << i << " past the count";
    }
  }
}

// The GPU deformer's path: positions rewritten in the backend's device copy, then update_device.
TEST(OptixRayTracer, DeviceUpdateFollowsPositionsWrittenOnTheGpu) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  Scene scene = testing::make_reduced_atrium();
  for (const UpdatePolicy policy : kAllUpdatePolicies) {
    Scene posed = scene;
    const auto tracer = backends::make_ray_tracer("optix");
    tracer->build(posed, {});
    DeviceTracing& device = *tracer->device_tracing();
    SceneDeformers deformers(posed);
    const std::vector<uint32_t> dirty = deformers.apply(posed, 40);
    ASSERT_FALSE(dirty.empty());
    for (const uint32_t m : dirty)
      ASSERT_EQ(cudaMemcpy(device.device_positions(m), posed.meshes[m].positions.data(),
                           posed.meshes[m].positions.size() * sizeof(vec3), cudaMemcpyHostToDevice),
                cudaSuccess);
    device.update_device(dirty, policy);
    const std::vector<accel::Ray> rays = random_rays(posed, 50000, 17);
    EXPECT_EQ(compare_hits_off_edges(posed, rays, cpu_hits(posed, rays), trace(*tracer, rays)), "")
        << update_policy_name(policy);
    EXPECT_EQ(tracer->stats().rebuilds + tracer->stats().refits, dirty.size());
  }
}

#endif  // GLINT_HAVE_OPTIX

}  // namespace
}  // namespace glint::rt
