// The optix backend's occlusion query (trace_any, trace_any_device: terminate on first hit) against a
// brute-force any-hit over the world triangles and against its own closest hits, before and after
// deformation, and through the device path with the ray count read on the GPU. Needs a build with
// OptiX and a CUDA GPU; skipped elsewhere (the GPU machine runs them: --gtest_filter='Optix*').
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

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace glint::rt {
namespace {

using testing::brute_force_occluded;
using testing::compare_occluded;
using testing::hit_exists;
using testing::occlusion_test_rays;
using testing::trace;
using testing::trace_occluded;

AccelOptions optix_options(optix::BuildPreference preference) {
  AccelOptions options;
  options.backend_structure = optix::kBuildPreferenceNames.name_of(preference);
  return options;
}

// OptiX's triangle test is not glint's: a ray grazing a mesh's outer border (silhouette) within float
// rounding may be decided either way (test_support.h). "" when at most 0.2 % of the rays (and at
// least 2 allowed) differ from brute force; else the report.
std::string compare_occluded_off_edges(std::span<const accel::Ray> rays, std::span<const uint8_t> expected,
                                       std::span<const uint8_t> actual) {
  size_t differences = 0;
  for (size_t i = 0; i < rays.size(); ++i) differences += expected[i] != actual[i] ? 1 : 0;
  if (differences <= std::max<size_t>(2, rays.size() / 500)) return "";
  return compare_occluded(rays, expected, actual);
}

TEST(OptixRayTracerOcclusion, EqualsBruteForceAndItsOwnClosestHits) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 8000, 7);
  const std::vector<uint8_t> expected = brute_force_occluded(scene, rays);
  // Shared interior edges and vertices: a watertight test hits them whatever its rounding.
  const std::vector<accel::Ray> edges = testing::edge_and_vertex_rays(scene, 4000, 11);
  for (const optix::BuildPreference preference : optix::kAllBuildPreferences) {
    const auto tracer = backends::make_ray_tracer("optix");
    tracer->build(scene, optix_options(preference));
    const std::vector<uint8_t> occluded = trace_occluded(*tracer, rays);
    EXPECT_EQ(compare_occluded_off_edges(rays, expected, occluded), "") << optix::kBuildPreferenceNames.name_of(preference);
    // The same triangle tests in both queries: exactly the rays with a closest hit are occluded.
    EXPECT_EQ(compare_occluded(rays, hit_exists(trace(*tracer, rays)), occluded), "") << optix::kBuildPreferenceNames.name_of(preference);
    EXPECT_EQ(compare_occluded(edges, std::vector<uint8_t>(edges.size(), 1), trace_occluded(*tracer, edges)), "")
        << optix::kBuildPreferenceNames.name_of(preference) << " edges";
  }
}

TEST(OptixRayTracerOcclusion, ReflectionRaysOnReducedAtriumAgreeWithClosestHits) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_reduced_atrium();
  std::vector<accel::Ray> rays = testing::reflection_like_rays(scene, 100000, 21);
  for (size_t i = 0; i < rays.size(); i += 3) rays[i].t_max = 2.0f;
  const auto tracer = backends::make_ray_tracer("optix");
  tracer->build(scene, {});
  EXPECT_EQ(compare_occluded(rays, hit_exists(trace(*tracer, rays)), trace_occluded(*tracer, rays)), "");
}

TEST(OptixRayTracerOcclusion, FollowsDeformationWithEveryPolicy) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  for (const UpdatePolicy policy : kAllUpdatePolicies) {
    Scene scene = testing::make_instanced_scene();
    const auto tracer = backends::make_ray_tracer("optix");
    tracer->build(scene, {});
    const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 4000, 5);
    const std::vector<uint8_t> rest = brute_force_occluded(scene, rays);
    SceneDeformers deformers(scene);
    for (int frame : {17, 40}) {
      tracer->update(scene, deformers.apply(scene, frame), policy);
      const std::vector<uint8_t> expected = brute_force_occluded(scene, rays);
      ASSERT_NE(compare_occluded(rays, rest, expected), "") << "the deformation must change some answers";
      EXPECT_EQ(compare_occluded_off_edges(rays, expected, trace_occluded(*tracer, rays)), "")
          << update_policy_name(policy) << " frame " << frame;
    }
  }
}

TEST(OptixRayTracerOcclusion, MisuseIsAClearError) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("optix");
  const std::vector<accel::Ray> rays(1);
  std::vector<uint8_t> occluded(1);
  EXPECT_NE(testing::error_of([&] { tracer->trace_any(rays, occluded); }).find("trace_any() before build()"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { (void)tracer->device_tracing()->trace_any_device(nullptr, nullptr, nullptr, 0); })
                .find("trace_any_device() before build()"),
            std::string::npos);
  tracer->build(scene, {});
  occluded.resize(2);
  EXPECT_NE(testing::error_of([&] { tracer->trace_any(rays, occluded); }).find("1 rays but 2 occlusion results"),
            std::string::npos);
  tracer->trace_any({}, {});  // nothing to trace is fine
}

#if GLINT_HAVE_OPTIX

// The renderer's shadow path: rays and one uint32 per ray in device memory, the ray count read on the
// GPU. Slots past the count keep their sentinel; the traced ones equal the host query's answers. A
// closest-hit launch between two occlusion launches (each query keeps its own launch parameters)
// leaves both right.
TEST(OptixRayTracerOcclusion, DeviceQueryStopsAtTheGpuSideRayCount) {
  GLINT_SKIP_WITHOUT_OPTIX_GPU();
  const Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("optix");
  tracer->build(scene, {});
  DeviceTracing& device = *tracer->device_tracing();
  const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 4000, 13);
  const std::vector<uint8_t> host = trace_occluded(*tracer, rays);
  const std::vector<accel::Hit> host_hits = trace(*tracer, rays);
  const auto traced = static_cast<uint32_t>(rays.size() / 2 + 7);
  constexpr uint32_t kSentinel = 0xDEADBEEFu;
  cuda::DeviceBuffer<accel::Ray> device_rays;
  device_rays.upload(rays);
  cuda::DeviceBuffer<uint32_t> device_occluded;
  device_occluded.upload(std::vector<uint32_t>(rays.size(), kSentinel));
  cuda::DeviceBuffer<accel::Hit> device_hits(rays.size());
  cuda::DeviceBuffer<uint32_t> count;
  count.upload(std::span<const uint32_t>(&traced, 1));
  const auto capacity = static_cast<uint32_t>(rays.size());
  device.drop_ticket(device.trace_any_device(device_rays.data(), device_occluded.data(), count.data(), capacity));
  device.drop_ticket(device.trace_closest_device(device_rays.data(), device_hits.data(), count.data(), capacity));
  const GpuTicket last = device.trace_any_device(device_rays.data(), device_occluded.data(), count.data(), capacity);
  ASSERT_EQ(cudaStreamSynchronize(static_cast<cudaStream_t>(device.stream())), cudaSuccess);
  EXPECT_GE(*device.gpu_ms(last, /*wait=*/true), 0.0);
  const std::vector<uint32_t> occluded = device_occluded.download();
  const std::vector<accel::Hit> hits = device_hits.download();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    if (i < traced) {
      ASSERT_EQ(occluded[i], host[i]) << "ray " << i;
      ASSERT_EQ(hits[i].valid(), host_hits[i].valid()) << "ray " << i;
    } else {
      ASSERT_EQ(occluded[i], kSentinel) << "slot " << i << " past the count";
    }
  }
}

#endif  // GLINT_HAVE_OPTIX

}  // namespace
}  // namespace glint::rt
