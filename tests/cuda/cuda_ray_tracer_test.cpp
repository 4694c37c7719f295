// The cuda backend against brute force and against the cpu backend, for every builder of the menu
// (GPU-built lbvh and ploc, CPU-built and uploaded the rest), before and after deformation with
// every update policy, and through its device-side entry points (rays, hits and the ray count in
// device memory, vertices rewritten on the GPU). Needs a CUDA GPU; skipped elsewhere, except the
// error cases that need none.
#include "cuda/cuda_ray_tracer.h"
#include "cuda/device_copies.h"
#include "cuda/device_query.h"
#include "backends/registry.h"
#include "rt/ray_tracer.h"
#include "rt/ray_tracer_check.h"
#include "rt/reflection_rays.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <initializer_list>

#if GLINT_HAVE_CUDA
#include <cuda_runtime.h>
#endif

namespace glint::rt {
namespace {

using testing::brute_force_hits;
using testing::compare_hits;
using testing::random_rays;
using testing::trace;

AccelOptions with_builder(accel::BvhBuilder builder) {
  AccelOptions options;
  options.builder = builder;
  return options;
}

TEST(CudaRayTracer, WithoutAGpuTheBackendIsOneClearError) {
  if (cuda_gpu_present()) GTEST_SKIP() << "a CUDA GPU is present";
  const std::string error = testing::error_of([] { (void)backends::make_ray_tracer("cuda"); });
  EXPECT_NE(error.find("--backend cuda"), std::string::npos) << error;
}

TEST(CudaRayTracer, EveryBuilderEqualsBruteForceOnAnInstancedScene) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = random_rays(scene, 3000, 7);
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    const auto tracer = backends::make_ray_tracer("cuda");
    EXPECT_EQ(tracer->name(), "cuda");
    ASSERT_NE(tracer->device_tracing(), nullptr);
    tracer->build(scene, with_builder(builder));
    EXPECT_EQ(compare_hits(scene, rays, expected, trace(*tracer, rays)), "") << accel::builder_name(builder);
    const RayTracerStats stats = tracer->stats();
    EXPECT_EQ(stats.backend, "cuda");
    EXPECT_GT(stats.memory_bytes, 0u);
  }
}

// The bar: the GPU structures give the cpu backend's hits on >= 100k reflection rays of the
// reduced atrium.
TEST(CudaRayTracer, EveryBuilderEqualsTheCpuBackendOn100kReflectionRays) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_reduced_atrium();
  const std::vector<accel::Ray> rays = testing::reflection_like_rays(scene, 100000, 21);
  const auto cpu = backends::make_ray_tracer("cpu");
  cpu->build(scene, {});
  const std::vector<accel::Hit> expected = trace(*cpu, rays);
  size_t hit_count = 0;
  for (const accel::Hit& hit : expected) hit_count += hit.valid() ? 1 : 0;
  ASSERT_GT(hit_count, rays.size() / 4) << "the rays must mostly hit something to test anything";
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    if (builder == accel::BvhBuilder::none) continue;  // brute force on 100k rays: covered above on fewer
    for (cuda::TraceKernel kernel : {cuda::TraceKernel::one_ray_per_thread, cuda::TraceKernel::persistent}) {
      const auto tracer = cuda::make_cuda_ray_tracer({kernel});
      tracer->build(scene, with_builder(builder));
      EXPECT_EQ(compare_hits(scene, rays, expected, trace(*tracer, rays)), "")
          << accel::builder_name(builder) << " " << cuda::trace_kernel_name(kernel);
    }
  }
}

// The cpu backend's SAH drift after refitting the same builder's BLASes through the same frames.
double cpu_refit_drift(Scene scene, accel::BvhBuilder builder, std::initializer_list<int> frames) {
  const auto tracer = backends::make_ray_tracer("cpu");
  tracer->build(scene, with_builder(builder));
  SceneDeformers deformers(scene);
  for (int frame : frames) tracer->update(scene, deformers.apply(scene, frame), UpdatePolicy::refit);
  return tracer->stats().blas_sah_drift.value_or(0.0);
}

void check_updates(Scene scene, accel::BvhBuilder builder, UpdatePolicy policy) {
  const Scene rest_scene = scene;
  const auto tracer = backends::make_ray_tracer("cuda");
  tracer->build(scene, with_builder(builder));
  SceneDeformers deformers(scene);
  const std::vector<accel::Ray> rays = random_rays(scene, 1500, 5);
  const std::vector<accel::Hit> rest = brute_force_hits(scene, rays);
  for (int frame : {17, 40, 41}) {
    const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
    ASSERT_FALSE(dirty.empty());
    tracer->update(scene, dirty, policy);
    const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
    ASSERT_NE(compare_hits(scene, rays, rest, expected), "") << "the deformation must change some hits";
    EXPECT_EQ(compare_hits(scene, rays, expected, trace(*tracer, rays)), "")
        << accel::builder_name(builder) << " " << update_policy_name(policy) << " frame " << frame;
  }
  const RayTracerStats stats = tracer->stats();
  EXPECT_EQ(stats.rebuilds + stats.refits, 3 * scene.deformable_meshes().size());
  if (policy == UpdatePolicy::rebuild) {
    EXPECT_EQ(stats.refits, 0u);
  }
  if (policy == UpdatePolicy::refit) {
    EXPECT_EQ(stats.rebuilds, 0u);
    ASSERT_TRUE(stats.blas_sah_drift.has_value());
    const double drift = *stats.blas_sah_drift;
    if (builder == accel::BvhBuilder::sah || builder == accel::BvhBuilder::trbvh) {
      // Built on the CPU and uploaded, refitted on the GPU from the same vertices: the same boxes as
      // the cpu backend's refit, so the same drift up to the GPU's float summation of the SAH.
      EXPECT_NEAR(drift, cpu_refit_drift(rest_scene, builder, {17, 40, 41}), 1e-3 * drift)
          << accel::builder_name(builder);
    } else {
      // Built on the GPU (another tree than the CPU's): a refit keeps the topology, so the cost
      // moves with the deformation but stays of the same order.
      EXPECT_GT(drift, 0.5) << accel::builder_name(builder);
      EXPECT_LT(drift, 2.0) << accel::builder_name(builder);
    }
  }
}

TEST(CudaRayTracer, UpdatesEqualBruteForceForEveryPolicyAndBuilder) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  for (accel::BvhBuilder builder :
       {accel::BvhBuilder::lbvh, accel::BvhBuilder::ploc, accel::BvhBuilder::sah, accel::BvhBuilder::trbvh}) {
    for (UpdatePolicy policy : kAllUpdatePolicies) check_updates(testing::make_instanced_scene(), builder, policy);
  }
  check_updates(testing::make_instanced_scene(), accel::BvhBuilder::sbvh, UpdatePolicy::rebuild);
}

TEST(CudaRayTracer, UpdateFollowsMovedInstances) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  for (UpdatePolicy policy : kAllUpdatePolicies) {
    Scene moved = testing::make_instanced_scene();
    const auto tracer = backends::make_ray_tracer("cuda");
    tracer->build(moved, {});
    moved.instances[5].transform[3] += vec4(0.5f, 1.0f, -0.25f, 0.0f);
    tracer->update(moved, {}, policy);
    const std::vector<accel::Ray> rays = random_rays(moved, 1000, 9);
    EXPECT_EQ(compare_hits(moved, rays, brute_force_hits(moved, rays), trace(*tracer, rays)), "")
        << update_policy_name(policy);
  }
}

TEST(CudaRayTracer, RefitOfASplitStructureIsAClearErrorAndChangesNothing) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("cuda");
  tracer->build(scene, with_builder(accel::BvhBuilder::sbvh));
  SceneDeformers deformers(scene);
  const std::vector<uint32_t> dirty = deformers.apply(scene, 10);
  const std::string error = testing::error_of([&] { tracer->update(scene, dirty, UpdatePolicy::refit); });
  EXPECT_NE(error.find("cannot be refitted"), std::string::npos) << error;
  EXPECT_EQ(tracer->stats().refits, 0u);
}

TEST(CudaRayTracer, MisuseIsAClearError) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  Scene scene = testing::make_instanced_scene();
  const auto tracer = backends::make_ray_tracer("cuda");
  std::vector<accel::Ray> rays(3);
  std::vector<accel::Hit> hits(3);
  EXPECT_NE(testing::error_of([&] { tracer->trace_closest(rays, hits); }).find("before build()"), std::string::npos);
  EXPECT_NE(testing::error_of([&] { tracer->update(scene, {}, UpdatePolicy::refit); }).find("before build()"),
            std::string::npos);
  tracer->build(scene, {});
  std::vector<accel::Hit> too_few(2);
  EXPECT_NE(testing::error_of([&] { tracer->trace_closest(rays, too_few); }).find("3 rays but 2 hits"),
            std::string::npos);
  const std::vector<uint32_t> out_of_range{99};
  EXPECT_NE(testing::error_of([&] { tracer->update(scene, out_of_range, UpdatePolicy::refit); })
                .find("dirty mesh index 99"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { (void)tracer->device_tracing()->device_positions(99); }).find("out of range"),
            std::string::npos);
}

#if GLINT_HAVE_CUDA
using testing::device_copy;
using testing::host_copy;

// What the hybrid renderer does: the ray count lives in device memory and only that many of the
// `capacity` slots are traced; the rest of the hit buffer is left alone.
TEST(CudaRayTracer, DeviceTraceReadsTheRayCountOnTheGpu) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = random_rays(scene, 2000, 13);
  const auto tracer = backends::make_ray_tracer("cuda");
  tracer->build(scene, {});
  DeviceTracing* device = tracer->device_tracing();
  const uint32_t traced = 1234;
  accel::Ray* device_rays = device_copy(rays);
  accel::Hit sentinel;
  sentinel.t = -7.0f;
  accel::Hit* device_hits = device_copy(std::vector<accel::Hit>(rays.size(), sentinel));
  uint32_t* device_count = device_copy(std::vector<uint32_t>{traced});
  const GpuTicket ticket =
      device->trace_closest_device(device_rays, device_hits, device_count, static_cast<uint32_t>(rays.size()));
  EXPECT_GE(*device->gpu_ms(ticket, /*wait=*/true), 0.0);  // waits for the trace
  const std::vector<accel::Hit> hits = host_copy(device_hits, rays.size());
  const std::span<const accel::Ray> traced_rays(rays.data(), traced);
  const std::vector<accel::Hit> expected = brute_force_hits(scene, traced_rays);
  EXPECT_EQ(compare_hits(scene, traced_rays, expected, std::span<const accel::Hit>(hits.data(), traced)), "");
  for (size_t i = traced; i < hits.size(); ++i) ASSERT_EQ(hits[i].t, -7.0f) << "slot " << i << " past the count";
  // The persistent kernel stops at the same count.
  const auto persistent_tracer = cuda::make_cuda_ray_tracer({cuda::TraceKernel::persistent});
  persistent_tracer->build(scene, {});
  DeviceTracing* persistent_device = persistent_tracer->device_tracing();
  const std::vector<accel::Hit> sentinels(rays.size(), sentinel);
  ASSERT_EQ(cudaMemcpy(device_hits, sentinels.data(), rays.size() * sizeof(accel::Hit), cudaMemcpyHostToDevice),
            cudaSuccess);
  const GpuTicket persistent_ticket = persistent_device->trace_closest_device(device_rays, device_hits, device_count,
                                                                             static_cast<uint32_t>(rays.size()));
  EXPECT_GE(*persistent_device->gpu_ms(persistent_ticket, /*wait=*/true), 0.0);
  const std::vector<accel::Hit> persistent_hits = host_copy(device_hits, rays.size());
  EXPECT_EQ(compare_hits(scene, traced_rays, expected, std::span<const accel::Hit>(persistent_hits.data(), traced)),
            "");
  for (size_t i = traced; i < hits.size(); ++i)
    ASSERT_EQ(persistent_hits[i].t, -7.0f) << "slot " << i << " past the count (persistent)";
  cudaFree(device_rays);
  cudaFree(device_hits);
  cudaFree(device_count);
}

// What the GPU deformer does: new positions written into device_positions(), then update_device.
TEST(CudaRayTracer, DeviceUpdateFollowsVerticesWrittenOnTheGpu) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  for (accel::BvhBuilder builder : {accel::BvhBuilder::lbvh, accel::BvhBuilder::sah}) {
    for (UpdatePolicy policy : kAllUpdatePolicies) {
      Scene scene = testing::make_instanced_scene();
      const auto tracer = backends::make_ray_tracer("cuda");
      tracer->build(scene, with_builder(builder));
      SceneDeformers deformers(scene);
      const std::vector<uint32_t> dirty = deformers.apply(scene, 23);
      DeviceTracing* device = tracer->device_tracing();
      for (uint32_t m : dirty) {
        const std::vector<vec3>& positions = scene.meshes[m].positions;
        ASSERT_EQ(cudaMemcpy(device->device_positions(m), positions.data(), positions.size() * sizeof(vec3),
                             cudaMemcpyHostToDevice),
                  cudaSuccess);
      }
      // The copies above ran on the legacy stream; the tracer's stream does not wait for it.
      ASSERT_EQ(cudaDeviceSynchronize(), cudaSuccess);
      device->update_device(dirty, policy);
      const std::vector<accel::Ray> rays = random_rays(scene, 1500, 17);
      EXPECT_EQ(compare_hits(scene, rays, brute_force_hits(scene, rays), trace(*tracer, rays)), "")
          << accel::builder_name(builder) << " " << update_policy_name(policy);
    }
  }
}
#endif

}  // namespace
}  // namespace glint::rt
