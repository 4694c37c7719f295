// The gl backend (GlRayTracer: glint's BVHs traversed in OpenGL compute shaders) against the
// brute-force references of tests/rt/ray_tracer_check.h: closest hits and occlusion for every BLAS
// builder, on the instanced test scene and the reduced atrium; the GL-side calls (rays, results and
// count in GL buffers, the count read on the GPU); updates after deformation by every policy; moved
// instances; misuse. Runs on whatever OpenGL 4.5 the machine has (llvmpipe here and in CI).
#include "gl_rt/gl_ray_tracer.h"
#include "backends/registry.h"

#include "accel/builders/builder.h"
#include "gl/gl_objects.h"
#include "gl/gl_test_context.h"
#include "gl/read_buffer.h"
#include "rt/ray_tracer.h"
#include "rt/ray_tracer_check.h"
#include "rt/reflection_rays.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <bit>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

namespace glint::gl_rt {
namespace {

using rt::AccelOptions;
using rt::UpdatePolicy;
using testing::brute_force_hits;
using testing::brute_force_occluded;
using testing::compare_hits;
using testing::compare_occluded;
using testing::hit_exists;
using testing::random_rays;
using testing::trace;
using testing::read_buffer;
using testing::trace_occluded;

using GlRayTracerTest = testing::GlTest;

AccelOptions with_builder(accel::BvhBuilder builder) {
  AccelOptions options;
  options.builder = builder;
  return options;
}

size_t count_ones(std::span<const uint8_t> flags) {
  size_t count = 0;
  for (uint8_t flag : flags) count += flag;
  return count;
}

// A GL buffer holding `data`, which the host may read back.
template <typename T>
GlBuffer buffer_of(const std::vector<T>& data) {
  return create_buffer(std::span<const T>(data), GL_DYNAMIC_STORAGE_BIT);
}

TEST(GlRayTracerContext, WithoutACurrentContextItIsOneClearError) {
  // A fresh thread has no current context, whatever other tests left on the main thread.
  std::string error;
  std::thread([&] { error = testing::error_of([] { (void)backends::make_ray_tracer("gl"); }); }).join();
  EXPECT_NE(error.find("--backend gl needs an OpenGL 4.5 context"), std::string::npos) << error;
}

TEST_F(GlRayTracerTest, MakeRayTracerGivesTheGlBackendWithGlTracing) {
  const auto tracer = backends::make_ray_tracer("gl");
  EXPECT_EQ(tracer->name(), "gl");
  EXPECT_EQ(tracer->gl_tracing(), dynamic_cast<GlRayTracer*>(tracer.get()));
  EXPECT_EQ(tracer->device_tracing(), nullptr);
  tracer->build(testing::make_instanced_scene(), {});
  const rt::RayTracerStats stats = tracer->stats();
  EXPECT_EQ(stats.backend, "gl");
  EXPECT_GT(stats.memory_bytes, 0u);
  EXPECT_GT(stats.build_ms, 0.0);
  EXPECT_EQ(stats.rebuilds + stats.refits, 0u);
  ASSERT_TRUE(stats.blas_sah_drift.has_value());  // the sheet is deformable
  EXPECT_DOUBLE_EQ(*stats.blas_sah_drift, 1.0);
}

TEST_F(GlRayTracerTest, EveryBuilderEqualsBruteForceOnTheInstancedScene) {
  const Scene scene = testing::make_instanced_scene();
  std::vector<accel::Ray> rays = random_rays(scene, 1500, 11);
  const std::vector<accel::Ray> reflection = testing::reflection_like_rays(scene, 1500, 12);
  rays.insert(rays.end(), reflection.begin(), reflection.end());
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  ASSERT_GT(count_ones(hit_exists(expected)), rays.size() / 4);
  GlRayTracer tracer;
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    tracer.build(scene, with_builder(builder));
    EXPECT_EQ(compare_hits(scene, rays, expected, trace(tracer, rays)), "") << accel::builder_name(builder);
  }
}

TEST_F(GlRayTracerTest, ClosestHitsEqualBruteForceAndTheCpuBackendOnTheReducedAtrium) {
  const Scene scene = testing::make_reduced_atrium();
  std::vector<accel::Ray> rays = random_rays(scene, 300, 3);
  const std::vector<accel::Ray> reflection = testing::reflection_like_rays(scene, 300, 4);
  rays.insert(rays.end(), reflection.begin(), reflection.end());
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  for (accel::BvhBuilder builder : {accel::BvhBuilder::sah, accel::BvhBuilder::lbvh}) {
    GlRayTracer tracer;
    tracer.build(scene, with_builder(builder));
    const std::vector<accel::Hit> hits = trace(tracer, rays);
    EXPECT_EQ(compare_hits(scene, rays, expected, hits), "") << accel::builder_name(builder);
    const auto cpu = backends::make_ray_tracer("cpu");
    cpu->build(scene, with_builder(builder));
    EXPECT_EQ(compare_hits(scene, rays, trace(*cpu, rays), hits), "") << "cpu vs gl " << accel::builder_name(builder);
  }
}

TEST_F(GlRayTracerTest, OcclusionEqualsBruteForceWithEveryBuilderIncludingEdgeAndIntervalRays) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = testing::occlusion_test_rays(scene, 1500, 7);
  const std::vector<uint8_t> expected = brute_force_occluded(scene, rays);
  ASSERT_GT(count_ones(expected), rays.size() / 4);
  ASSERT_LT(count_ones(expected), rays.size() * 3 / 4);
  GlRayTracer tracer;
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    tracer.build(scene, with_builder(builder));
    const std::vector<uint8_t> occluded = trace_occluded(tracer, rays);
    EXPECT_EQ(compare_occluded(rays, expected, occluded), "") << accel::builder_name(builder);
    EXPECT_EQ(compare_occluded(rays, hit_exists(trace(tracer, rays)), occluded), "")
        << accel::builder_name(builder) << " vs its closest hits";
  }
}

TEST_F(GlRayTracerTest, EdgeAndVertexRaysOfTheReducedAtriumAreAllOccluded) {
  const Scene scene = testing::make_reduced_atrium();
  const std::vector<accel::Ray> rays = testing::edge_and_vertex_rays(scene, 400, 21);
  ASSERT_GT(rays.size(), 400u);
  GlRayTracer tracer;
  tracer.build(scene, {});
  EXPECT_EQ(compare_occluded(rays, std::vector<uint8_t>(rays.size(), 1), trace_occluded(tracer, rays)), "");
}

// The GL-side calls: the list's count is the first uint of a GL buffer, smaller than the capacity;
// slots at or past it keep what they held; the traced ones equal the host-side calls' answers.
TEST_F(GlRayTracerTest, GlSideTracesReadTheCountOnTheGpuAndLeaveLaterSlotsAlone) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = testing::occlusion_test_rays(scene, 300, 5);
  GlRayTracer tracer;
  tracer.build(scene, {});
  const std::vector<accel::Hit> host_hits = trace(tracer, rays);
  const std::vector<uint8_t> host_occluded = trace_occluded(tracer, rays);
  ASSERT_GT(count_ones(host_occluded), 0u);

  const auto capacity = static_cast<uint32_t>(rays.size());
  const GlBuffer ray_buffer = buffer_of(rays);
  constexpr uint32_t kSentinel = 0xABABABABu;
  accel::Hit sentinel_hit;
  sentinel_hit.t = std::bit_cast<float>(kSentinel);
  sentinel_hit.instance = sentinel_hit.prim = kSentinel;
  sentinel_hit.u = sentinel_hit.v = std::bit_cast<float>(kSentinel);
  for (uint32_t count : {capacity * 2 / 3, capacity, capacity + 50, 0u}) {
    // {count, a second counter}: only the first uint is the count.
    const GlBuffer count_buffer = buffer_of(std::vector<uint32_t>{count, 7u});
    const GlBuffer hit_buffer = buffer_of(std::vector<accel::Hit>(capacity, sentinel_hit));
    const GlBuffer occluded_buffer = buffer_of(std::vector<uint32_t>(capacity, kSentinel));
    rt::GlTracing& gl = *tracer.gl_tracing();
    gl.trace_closest_gl(ray_buffer.id(), hit_buffer.id(), count_buffer.id(), capacity);
    gl.trace_any_gl(ray_buffer.id(), occluded_buffer.id(), count_buffer.id(), capacity);
    const std::vector<accel::Hit> hits = read_buffer<accel::Hit>(hit_buffer.id(), 0, capacity);
    const std::vector<uint32_t> occluded = read_buffer<uint32_t>(occluded_buffer.id(), 0, capacity);
    const uint32_t traced = std::min(count, capacity);
    size_t wrong = 0, written_past = 0;
    for (uint32_t i = 0; i < capacity; ++i) {
      if (i < traced) {
        wrong += std::memcmp(&hits[i], &host_hits[i], sizeof(accel::Hit)) != 0 ? 1 : 0;
        wrong += occluded[i] != host_occluded[i] ? 1 : 0;
      } else {
        written_past += std::memcmp(&hits[i], &sentinel_hit, sizeof(accel::Hit)) != 0 ? 1 : 0;
        written_past += occluded[i] != kSentinel ? 1 : 0;
      }
    }
    EXPECT_EQ(wrong, 0u) << "count " << count;
    EXPECT_EQ(written_past, 0u) << "count " << count;
  }
  tracer.check_stack_overflow();  // nothing overflowed
}

// A list longer than one dispatch's work groups is traced in several dispatches (ray_base): the same
// answers, host side and GL side (count below the capacity, in the last piece).
TEST_F(GlRayTracerTest, ListsLongerThanOneDispatchAreTracedInPieces) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = testing::occlusion_test_rays(scene, 300, 15);
  GlRayTracer whole;
  GlRayTracer pieces(3);  // 192 rays per dispatch
  whole.build(scene, {});
  pieces.build(scene, {});
  ASSERT_GT(rays.size(), 4u * 192u);
  const std::vector<accel::Hit> hits = trace(whole, rays);
  EXPECT_EQ(compare_hits(scene, rays, hits, trace(pieces, rays)), "");
  EXPECT_EQ(compare_occluded(rays, trace_occluded(whole, rays), trace_occluded(pieces, rays)), "");

  const auto capacity = static_cast<uint32_t>(rays.size());
  const uint32_t count = capacity - 100;
  const GlBuffer ray_buffer = buffer_of(rays);
  const GlBuffer count_buffer = buffer_of(std::vector<uint32_t>{count});
  const GlBuffer hit_buffer = buffer_of(std::vector<accel::Hit>(capacity));
  pieces.trace_closest_gl(ray_buffer.id(), hit_buffer.id(), count_buffer.id(), capacity);
  const std::vector<accel::Hit> gl_hits = read_buffer<accel::Hit>(hit_buffer.id(), 0, capacity);
  size_t wrong = 0, written_past = 0;
  for (uint32_t i = 0; i < capacity; ++i) {
    if (i < count) wrong += gl_hits[i].prim != hits[i].prim || gl_hits[i].instance != hits[i].instance ? 1 : 0;
    else written_past += gl_hits[i].valid() ? 1 : 0;
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(written_past, 0u);
  EXPECT_NE(testing::error_of([] { GlRayTracer none(0); }).find("work groups per dispatch"), std::string::npos);
}

// Deforms, updates with `policy` and checks closest hits and occlusion against brute force on the
// deformed geometry, on two frames (a second update on top of a refit too).
void check_updates(Scene scene, const AccelOptions& options, UpdatePolicy policy, size_t ray_count) {
  GlRayTracer tracer;
  tracer.build(scene, options);
  SceneDeformers deformers(scene);
  const std::vector<accel::Ray> rays = random_rays(scene, ray_count, 5);
  const std::vector<accel::Hit> rest = brute_force_hits(scene, rays);
  const std::string label = std::string(accel::builder_name(options.builder)) + " " +
                            std::string(rt::update_policy_name(policy));
  for (int frame : {17, 40}) {
    const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
    ASSERT_FALSE(dirty.empty());
    tracer.update(scene, dirty, policy);
    const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
    ASSERT_NE(compare_hits(scene, rays, rest, expected), "") << "the deformation must change some hits";
    EXPECT_EQ(compare_hits(scene, rays, expected, trace(tracer, rays)), "") << label << " frame " << frame;
    const std::vector<accel::Ray> edges = testing::edge_and_vertex_rays(scene, 200, 3);
    std::vector<accel::Ray> occlusion_rays = rays;
    occlusion_rays.insert(occlusion_rays.end(), edges.begin(), edges.end());
    EXPECT_EQ(compare_occluded(occlusion_rays, brute_force_occluded(scene, occlusion_rays),
                               trace_occluded(tracer, occlusion_rays)),
              "")
        << label << " frame " << frame << " occlusion";
  }
  const rt::RayTracerStats stats = tracer.stats();
  EXPECT_EQ(stats.rebuilds + stats.refits, 2 * scene.deformable_meshes().size()) << label;
  if (policy == UpdatePolicy::rebuild) {
    EXPECT_EQ(stats.refits, 0u) << label;
  }
  if (policy == UpdatePolicy::refit) {
    EXPECT_EQ(stats.rebuilds, 0u) << label;
    ASSERT_TRUE(stats.blas_sah_drift.has_value());
    EXPECT_GT(*stats.blas_sah_drift, 1.0) << label << ": refitting a moved mesh degrades its BVH";
  }
  EXPECT_GT(stats.last_update_ms, 0.0);
}

TEST_F(GlRayTracerTest, UpdatesEqualBruteForceOnTheDeformedInstancedScene) {
  for (accel::BvhBuilder builder : {accel::BvhBuilder::sah, accel::BvhBuilder::lbvh, accel::BvhBuilder::ploc})
    for (UpdatePolicy policy : rt::kAllUpdatePolicies)
      check_updates(testing::make_instanced_scene(16), with_builder(builder), policy, 1000);
  // sbvh rebuilds (its duplicated references may outgrow the regions laid out at build()).
  check_updates(testing::make_instanced_scene(16), with_builder(accel::BvhBuilder::sbvh), UpdatePolicy::rebuild, 1000);
}

TEST_F(GlRayTracerTest, UpdatesEqualBruteForceOnTheDeformedReducedAtrium) {
  for (UpdatePolicy policy : rt::kAllUpdatePolicies) check_updates(testing::make_reduced_atrium(), {}, policy, 200);
}

TEST_F(GlRayTracerTest, AutomaticPolicyRebuildsPastTheThresholdAndRefitsBelowIt) {
  for (const auto& [ratio, expect_rebuilds] : {std::pair{1.0f, true}, std::pair{1000.0f, false}}) {
    Scene scene = testing::make_instanced_scene(16);
    AccelOptions options;
    options.auto_rebuild_sah_ratio = ratio;
    GlRayTracer tracer;
    tracer.build(scene, options);
    SceneDeformers deformers(scene);
    for (int frame : {10, 30}) tracer.update(scene, deformers.apply(scene, frame), UpdatePolicy::automatic);
    const rt::RayTracerStats stats = tracer.stats();
    EXPECT_EQ(expect_rebuilds ? stats.rebuilds : stats.refits, 2 * deformers.meshes().size()) << "ratio " << ratio;
    const std::vector<accel::Ray> rays = random_rays(scene, 500, 8);
    EXPECT_EQ(compare_hits(scene, rays, brute_force_hits(scene, rays), trace(tracer, rays)), "") << "ratio " << ratio;
  }
}

TEST_F(GlRayTracerTest, SbvhRefitIsRefusedAndLeavesTheStructuresAsTheyWere) {
  Scene scene = testing::make_instanced_scene();
  GlRayTracer tracer;
  tracer.build(scene, with_builder(accel::BvhBuilder::sbvh));
  const std::vector<accel::Ray> rays = random_rays(scene, 500, 4);
  const std::vector<accel::Hit> before = brute_force_hits(scene, rays);
  const Scene rest = scene;
  SceneDeformers deformers(scene);
  const std::vector<uint32_t> dirty = deformers.apply(scene, 9);
  for (UpdatePolicy policy : {UpdatePolicy::refit, UpdatePolicy::automatic}) {
    const std::string error = testing::error_of([&] { tracer.update(scene, dirty, policy); });
    EXPECT_NE(error.find("rt gl: update policy"), std::string::npos) << error;
    EXPECT_NE(error.find("sbvh"), std::string::npos) << error;
    EXPECT_NE(error.find("cannot be refitted"), std::string::npos) << error;
  }
  EXPECT_EQ(compare_hits(rest, rays, before, trace(tracer, rays)), "") << "a refused update changed the structures";
  tracer.update(scene, dirty, UpdatePolicy::rebuild);
  EXPECT_EQ(compare_hits(scene, rays, brute_force_hits(scene, rays), trace(tracer, rays)), "");
}

// An sbvh rebuild whose split references outgrow the regions laid out at build() lays everything out
// again: a mesh of small separate triangles (no splits) becomes long overlapping slivers (many).
TEST_F(GlRayTracerTest, SbvhRebuildThatOutgrowsItsRegionIsLaidOutAgain) {
  Scene scene = testing::make_instanced_scene();
  Mesh slivers;
  slivers.name = "slivers";
  slivers.material = 1;
  constexpr uint32_t kTriangles = 64;
  for (uint32_t i = 0; i < kTriangles; ++i) {
    const float x = 0.3f * static_cast<float>(i);
    for (const vec3& p : {vec3(x, 0, 0), vec3(x + 0.1f, 0, 0), vec3(x, 0.1f, 0)}) {
      slivers.positions.push_back(p + vec3(-8, 6, 3));
      slivers.normals.push_back(vec3(0, 0, 1));
    }
    for (uint32_t k = 0; k < 3; ++k) slivers.indices.push_back(3 * i + k);
  }
  scene.meshes.push_back(slivers);
  const auto mesh = static_cast<uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back({"slivers", mesh, mat4(1.0f)});
  scene.validate();
  GlRayTracer tracer;
  tracer.build(scene, with_builder(accel::BvhBuilder::sbvh));
  const uint64_t bytes_at_build = tracer.stats().memory_bytes;
  std::vector<vec3>& positions = scene.meshes[mesh].positions;
  for (uint32_t i = 0; i < kTriangles; ++i) {
    const float y = 0.05f * static_cast<float>(i);
    positions[3 * i] = vec3(-8, 6 + y, 3);
    positions[3 * i + 1] = vec3(12, 6 + y + 2, 3.5f);
    positions[3 * i + 2] = vec3(-8, 6 + y + 0.3f, 2 + 0.1f * static_cast<float>(i % 7));
  }
  const std::vector<uint32_t> dirty{mesh};
  tracer.update(scene, dirty, UpdatePolicy::rebuild);
  EXPECT_GT(tracer.stats().memory_bytes, bytes_at_build) << "the slivers' sbvh did not outgrow its region";
  std::vector<accel::Ray> rays = random_rays(scene, 1500, 13);
  const std::vector<accel::Hit> expected = brute_force_hits(scene, rays);
  EXPECT_EQ(compare_hits(scene, rays, expected, trace(tracer, rays)), "");
  EXPECT_EQ(compare_occluded(rays, hit_exists(expected), trace_occluded(tracer, rays)), "");
}

TEST_F(GlRayTracerTest, UpdateFollowsMovedInstances) {
  Scene scene = testing::make_instanced_scene();
  GlRayTracer tracer;
  tracer.build(scene, {});
  scene.instances[2].transform = glm::translate(mat4(1.0f), vec3(0.5f, 2.0f, -1.0f)) * scene.instances[2].transform;
  scene.instances[5].transform = glm::rotate(scene.instances[5].transform, 0.7f, vec3(0, 1, 0));
  tracer.update(scene, {}, UpdatePolicy::refit);
  const std::vector<accel::Ray> rays = random_rays(scene, 1500, 9);
  EXPECT_EQ(compare_hits(scene, rays, brute_force_hits(scene, rays), trace(tracer, rays)), "");
  EXPECT_EQ(compare_occluded(rays, brute_force_occluded(scene, rays), trace_occluded(tracer, rays)), "");
}

TEST_F(GlRayTracerTest, EmptyRayListsAreFine) {
  GlRayTracer tracer;
  tracer.build(testing::make_instanced_scene(), {});
  tracer.trace_closest({}, {});
  tracer.trace_any({}, {});
  tracer.trace_closest_gl(0, 0, 0, 0);
  tracer.trace_any_gl(0, 0, 0, 0);
}

TEST_F(GlRayTracerTest, MisuseIsAClearError) {
  const Scene scene = testing::make_instanced_scene();
  GlRayTracer tracer;
  std::vector<accel::Ray> rays(3);
  std::vector<accel::Hit> hits(3);
  std::vector<uint8_t> occluded(3);
  EXPECT_NE(testing::error_of([&] { tracer.trace_closest(rays, hits); }).find("rt gl: trace_closest() before build()"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { tracer.trace_any(rays, occluded); }).find("rt gl: trace_any() before build()"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { tracer.trace_closest_gl(1, 2, 3, 3); }).find("before build()"), std::string::npos);
  EXPECT_NE(testing::error_of([&] { tracer.trace_any_gl(1, 2, 3, 3); }).find("before build()"), std::string::npos);
  EXPECT_NE(testing::error_of([&] { tracer.update(scene, {}, UpdatePolicy::refit); }).find("before build()"),
            std::string::npos);
  AccelOptions low;
  low.auto_rebuild_sah_ratio = 0.5f;
  EXPECT_NE(testing::error_of([&] { tracer.build(scene, low); }).find("auto_rebuild_sah_ratio"), std::string::npos);

  tracer.build(scene, {});
  std::vector<accel::Hit> too_few(2);
  EXPECT_NE(testing::error_of([&] { tracer.trace_closest(rays, too_few); }).find("3 rays but room for 2 results"),
            std::string::npos);
  std::vector<uint8_t> too_many(4);
  EXPECT_NE(testing::error_of([&] { tracer.trace_any(rays, too_many); }).find("3 rays but 4 occlusion results"),
            std::string::npos);
  const std::vector<uint32_t> out_of_range{99};
  EXPECT_NE(testing::error_of([&] { tracer.update(scene, out_of_range, UpdatePolicy::refit); }).find("dirty mesh index 99"),
            std::string::npos);
  Scene grown = scene;
  grown.meshes[2].positions.push_back(vec3(0.0f));
  grown.meshes[2].normals.push_back(vec3(0, 0, 1));
  const std::vector<uint32_t> sheet{2};
  EXPECT_NE(testing::error_of([&] { tracer.update(grown, sheet, UpdatePolicy::rebuild); }).find("build() again"),
            std::string::npos);
}

}  // namespace
}  // namespace glint::gl_rt
