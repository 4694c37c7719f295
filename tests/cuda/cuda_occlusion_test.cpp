// The cuda backend's occlusion query (trace_any, trace_any_device) against a brute-force any-hit over
// the world triangles and against its own closest hits, for every builder and both trace kernels,
// after deformation with every policy, and through the device path with the ray count read on the
// GPU. Needs a CUDA GPU; skipped elsewhere.
#include "cuda/cuda_ray_tracer.h"
#include "cuda/device_copies.h"
#include "cuda/device_query.h"
#include "backends/registry.h"
#include "rt/ray_tracer.h"
#include "rt/hit_shadow_ray.h"
#include "rt/ray_tracer_check.h"
#include "rt/reflection_rays.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#if GLINT_HAVE_CUDA
#include <cuda_runtime.h>
#endif

namespace glint::rt {
namespace {

using testing::brute_force_occluded;
using testing::compare_occluded;
using testing::hit_exists;
using testing::occlusion_test_rays;
using testing::trace;
using testing::trace_occluded;

constexpr cuda::TraceKernel kKernels[] = {cuda::TraceKernel::one_ray_per_thread, cuda::TraceKernel::persistent};

AccelOptions cuda_options(accel::BvhBuilder builder) {
  AccelOptions options;
  options.builder = builder;
  return options;
}

TEST(CudaRayTracerOcclusion, EveryBuilderAndKernelEqualsBruteForce) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 3000, 7);
  const std::vector<uint8_t> expected = brute_force_occluded(scene, rays);
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    for (cuda::TraceKernel kernel : kKernels) {
      const auto tracer = cuda::make_cuda_ray_tracer({kernel});
      tracer->build(scene, cuda_options(builder));
      const std::vector<uint8_t> occluded = trace_occluded(*tracer, rays);
      const std::string label = std::string(accel::builder_name(builder)) + " " + std::string(cuda::trace_kernel_name(kernel));
      EXPECT_EQ(compare_occluded(rays, expected, occluded), "") << label;
      EXPECT_EQ(compare_occluded(rays, hit_exists(trace(*tracer, rays)), occluded), "") << label << " vs closest";
    }
  }
}

// Watertightness on the GPU: rays aimed exactly at shared edges and vertices are all occluded; and
// reflection rays agree with the closest hits (the renderer's rays, 100k).
TEST(CudaRayTracerOcclusion, EdgeRaysAreOccludedAndReflectionRaysAgreeWithClosestHits) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_reduced_atrium();
  const std::vector<accel::Ray> edges = testing::edge_and_vertex_rays(scene, 5000, 5);
  std::vector<accel::Ray> reflections = testing::reflection_like_rays(scene, 100000, 21);
  for (size_t i = 0; i < reflections.size(); i += 3) reflections[i].t_max = 2.0f;
  for (accel::BvhBuilder builder : {accel::BvhBuilder::lbvh, accel::BvhBuilder::ploc, accel::BvhBuilder::sah}) {
    const auto tracer = backends::make_ray_tracer("cuda");
    tracer->build(scene, cuda_options(builder));
    EXPECT_EQ(compare_occluded(edges, std::vector<uint8_t>(edges.size(), 1), trace_occluded(*tracer, edges)), "")
        << accel::builder_name(builder);
    EXPECT_EQ(compare_occluded(reflections, hit_exists(trace(*tracer, reflections)), trace_occluded(*tracer, reflections)),
              "")
        << accel::builder_name(builder);
  }
}

TEST(CudaRayTracerOcclusion, FollowsDeformationWithEveryPolicy) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  for (accel::BvhBuilder builder : {accel::BvhBuilder::lbvh, accel::BvhBuilder::ploc, accel::BvhBuilder::sah}) {
    for (UpdatePolicy policy : kAllUpdatePolicies) {
      Scene scene = testing::make_instanced_scene();
      const auto tracer = backends::make_ray_tracer("cuda");
      tracer->build(scene, cuda_options(builder));
      const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 1500, 5);
      const std::vector<uint8_t> rest = brute_force_occluded(scene, rays);
      SceneDeformers deformers(scene);
      for (int frame : {17, 40, 41}) {
        tracer->update(scene, deformers.apply(scene, frame), policy);
        const std::vector<uint8_t> expected = brute_force_occluded(scene, rays);
        ASSERT_NE(compare_occluded(rays, rest, expected), "") << "the deformation must change some answers";
        EXPECT_EQ(compare_occluded(rays, expected, trace_occluded(*tracer, rays)), "")
            << accel::builder_name(builder) << " " << update_policy_name(policy) << " frame " << frame;
      }
    }
  }
}

TEST(CudaRayTracerOcclusion, MisuseIsAClearError) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("cuda");
  const std::vector<accel::Ray> rays(3);
  std::vector<uint8_t> occluded(3);
  EXPECT_NE(testing::error_of([&] { tracer->trace_any(rays, occluded); }).find("trace_any() before build()"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { (void)tracer->device_tracing()->trace_any_device(nullptr, nullptr, nullptr, 0); })
                .find("trace_any_device() before build()"),
            std::string::npos);
  tracer->build(scene, {});
  std::vector<uint8_t> too_few(2);
  EXPECT_NE(testing::error_of([&] { tracer->trace_any(rays, too_few); }).find("3 rays but 2 occlusion results"),
            std::string::npos);
  tracer->trace_any({}, {});  // nothing to trace is fine
}

#if GLINT_HAVE_CUDA
using testing::device_copy;
using testing::host_copy;

// The renderer's shadow path: rays and one uint32 per ray in device memory, the ray count read on the
// GPU; only that many slots are written (the rest keep their sentinel), with both trace kernels, and
// a closest-hit launch in between does not disturb either.
TEST(CudaRayTracerOcclusion, DeviceQueryReadsTheRayCountOnTheGpu) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 2000, 13);
  const auto traced = static_cast<uint32_t>(rays.size() / 2 + 7);
  const std::span<const accel::Ray> traced_rays(rays.data(), traced);
  const std::vector<uint8_t> expected = brute_force_occluded(scene, traced_rays);
  constexpr uint32_t kSentinel = 0xDEADBEEFu;
  accel::Ray* device_rays = device_copy(rays);
  uint32_t* device_occluded = device_copy(std::vector<uint32_t>(rays.size(), kSentinel));
  accel::Hit* device_hits = device_copy(std::vector<accel::Hit>(rays.size()));
  uint32_t* device_count = device_copy(std::vector<uint32_t>{traced});
  for (cuda::TraceKernel kernel : kKernels) {
    const auto tracer = cuda::make_cuda_ray_tracer({kernel});
    tracer->build(scene, cuda_options(accel::BvhBuilder::sah));
    DeviceTracing* device = tracer->device_tracing();
    ASSERT_EQ(cudaMemcpy(device_occluded, std::vector<uint32_t>(rays.size(), kSentinel).data(),
                         rays.size() * sizeof(uint32_t), cudaMemcpyHostToDevice),
              cudaSuccess);
    const GpuTicket first =
        device->trace_any_device(device_rays, device_occluded, device_count, static_cast<uint32_t>(rays.size()));
    device->drop_ticket(
        device->trace_closest_device(device_rays, device_hits, device_count, static_cast<uint32_t>(rays.size())));
    const GpuTicket last =
        device->trace_any_device(device_rays, device_occluded, device_count, static_cast<uint32_t>(rays.size()));
    EXPECT_GE(*device->gpu_ms(last, /*wait=*/true), 0.0);  // waits for the last launch
    EXPECT_GE(*device->gpu_ms(first, /*wait=*/false), 0.0) << "an earlier trace keeps its own time";
    const std::vector<uint32_t> occluded = host_copy(device_occluded, rays.size());
    const std::vector<accel::Hit> hits = host_copy(device_hits, traced);
    std::vector<uint8_t> traced_occluded(traced);
    for (uint32_t i = 0; i < traced; ++i) {
      ASSERT_LE(occluded[i], 1u) << "slot " << i;
      traced_occluded[i] = static_cast<uint8_t>(occluded[i]);
    }
    const std::string kernel_name(cuda::trace_kernel_name(kernel));
    EXPECT_EQ(compare_occluded(traced_rays, expected, traced_occluded), "") << kernel_name;
    EXPECT_EQ(compare_occluded(traced_rays, hit_exists(hits), traced_occluded), "") << kernel_name << " vs closest";
    for (size_t i = traced; i < rays.size(); ++i)
      ASSERT_EQ(occluded[i], kSentinel) << "slot " << i << " past the count (" << kernel_name << ")";
  }
  cudaFree(device_rays);
  cudaFree(device_occluded);
  cudaFree(device_hits);
  cudaFree(device_count);
}

// The reflection hits' shadow rays traced with the hits (what the renderer does with rt shadows):
// slot i's shadow ray is rt::hit_shadow_ray of ray i's hit, computed here on the host from the scene,
// and its answer is the brute-force occlusion of that ray; slots past the count are not written.
TEST(CudaRayTracerOcclusion, HitShadowRaysAreTracedWithTheHits) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  Scene scene = testing::make_instanced_scene();
  SceneDeformers(scene).apply(scene, 23);  // bent meshes: hits on every side of the light
  const std::vector<accel::Ray> rays = testing::reflection_like_rays(scene, 3000, 11);
  const auto capacity = static_cast<uint32_t>(rays.size());
  const uint32_t traced = capacity - 101;
  const vec3 light = scene.world_bounds().center() + vec3(0.0f, 0.3f, 0.1f) * length(scene.world_bounds().extent());
  const float offset = 1e-4f * length(scene.world_bounds().extent());
  const auto tracer = backends::make_ray_tracer("cuda");
  tracer->build(scene, {});
  DeviceTracing* device = tracer->device_tracing();
  ASSERT_TRUE(device->traces_hit_shadows());
  accel::Ray* device_rays = device_copy(rays);
  accel::Hit* device_hits = device_copy(std::vector<accel::Hit>(rays.size()));
  uint32_t* device_count = device_copy(std::vector<uint32_t>{traced});
  accel::Ray sentinel_ray;
  sentinel_ray.t_min = -9.0f;
  accel::Ray* device_shadow_rays = device_copy(std::vector<accel::Ray>(rays.size(), sentinel_ray));
  constexpr uint32_t kSentinel = 0xDEADBEEFu;
  uint32_t* device_occluded = device_copy(std::vector<uint32_t>(rays.size(), kSentinel));
  const HitAndShadowTickets tickets = device->trace_closest_and_hit_shadows_device(
      device_rays, device_hits, device_count, capacity, {light, offset, device_shadow_rays, device_occluded});
  EXPECT_GE(*device->gpu_ms(tickets.shadows, /*wait=*/true), 0.0);
  EXPECT_GE(*device->gpu_ms(tickets.closest, /*wait=*/false), 0.0);
  const std::vector<accel::Hit> hits = host_copy(device_hits, traced);
  const std::vector<accel::Ray> shadow_rays = host_copy(device_shadow_rays, rays.size());
  const std::vector<uint32_t> occluded = host_copy(device_occluded, rays.size());
  const std::span<const accel::Ray> traced_rays(rays.data(), traced);
  EXPECT_EQ(testing::compare_hits(scene, traced_rays, testing::brute_force_hits(scene, traced_rays), hits), "");
  int cast = 0;
  for (uint32_t i = 0; i < traced; ++i) {
    accel::Ray expected = empty_shadow_ray();
    if (hits[i].valid()) {
      const Instance& instance = scene.instances[hits[i].instance];
      const Mesh& mesh = scene.meshes[instance.mesh];
      const auto corner = [&](int k) {
        return vec3(instance.transform * vec4(mesh.positions[mesh.indices[3 * hits[i].prim + k]], 1.0f));
      };
      expected = hit_shadow_ray(rays[i], hits[i].u, hits[i].v, corner(0), corner(1), corner(2), light, offset);
    }
    ASSERT_EQ(expected.t_min > expected.t_max, shadow_rays[i].t_min > shadow_rays[i].t_max) << "slot " << i;
    ASSERT_LT(length(expected.origin - shadow_rays[i].origin), 1e-5f * length(scene.world_bounds().extent()))
        << "slot " << i;
    cast += expected.t_min <= expected.t_max;
  }
  EXPECT_GT(cast, static_cast<int>(traced) / 4);
  const std::span<const accel::Ray> traced_shadow_rays(shadow_rays.data(), traced);
  std::vector<uint8_t> answers(traced);
  for (uint32_t i = 0; i < traced; ++i) {
    ASSERT_LE(occluded[i], 1u) << "slot " << i;
    answers[i] = static_cast<uint8_t>(occluded[i]);
  }
  EXPECT_EQ(compare_occluded(traced_shadow_rays, brute_force_occluded(scene, traced_shadow_rays), answers), "");
  for (uint32_t i = traced; i < capacity; ++i) {
    ASSERT_EQ(occluded[i], kSentinel) << "slot " << i << " past the count";
    ASSERT_EQ(shadow_rays[i].t_min, -9.0f) << "slot " << i << " past the count";
  }
  for (void* pointer : std::initializer_list<void*>{device_rays, device_hits, device_count, device_shadow_rays,
                                                    device_occluded})
    cudaFree(pointer);
}

// Every device-side trace keeps its GPU time under its own ticket until it is read, however many
// traces come after (a frame of 64 reflection samples traces over a hundred; the backend once kept
// the last 64). A time is read once: asking again, or for a dropped or never issued ticket, is a
// clear error, not another trace's time.
TEST(CudaRayTracerOcclusion, GpuTimesAreKeptPerTicketUntilRead) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("cuda");
  tracer->build(scene, {});
  DeviceTracing* device = tracer->device_tracing();
  const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 64, 3);
  accel::Ray* device_rays = device_copy(rays);
  uint32_t* device_occluded = device_copy(std::vector<uint32_t>(rays.size(), 0));
  const auto count = static_cast<uint32_t>(rays.size());
  std::vector<GpuTicket> tickets;
  for (int i = 0; i < 200; ++i) tickets.push_back(device->trace_any_device(device_rays, device_occluded, nullptr, count));
  EXPECT_GE(*device->gpu_ms(tickets.back(), /*wait=*/true), 0.0);
  for (std::size_t i = 0; i + 1 < tickets.size(); ++i)  // done before the last: no wait needed
    EXPECT_GE(device->gpu_ms(tickets[i], /*wait=*/false).value_or(-1.0), 0.0) << "trace " << i;
  EXPECT_NE(testing::error_of([&] { (void)device->gpu_ms(tickets[0], true); }).find("after it was read or let go"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { (void)device->gpu_ms(tickets.back() + 1, true); }).find("spans were started"),
            std::string::npos);
  const GpuTicket dropped = device->trace_any_device(device_rays, device_occluded, nullptr, count);
  device->drop_ticket(dropped);
  EXPECT_NE(testing::error_of([&] { (void)device->gpu_ms(dropped, true); }).find("after it was read or let go"),
            std::string::npos);
  EXPECT_FALSE(device->last_update().has_value());
  // An update's time outlives the traces after it (what a frame of many samples does before the
  // frame loop reads its update), for its reader and for stats().
  tracer->update(scene, {}, UpdatePolicy::refit);
  const std::optional<GpuTicket> update = device->last_update();
  ASSERT_TRUE(update.has_value());
  for (int i = 0; i < 200; ++i)
    EXPECT_GE(*device->gpu_ms(device->trace_any_device(device_rays, device_occluded, nullptr, count), true), 0.0);
  const double update_ms = device->gpu_ms(*update, /*wait=*/true).value();
  EXPECT_GE(update_ms, 0.0);
  EXPECT_EQ(tracer->stats().last_update_ms, update_ms);
  cudaFree(device_rays);
  cudaFree(device_occluded);
}
#endif

}  // namespace
}  // namespace glint::rt
