// The occlusion query (RayTracer::trace_any) of the CPU backends against a brute-force any-hit over
// the flattened world triangles (same watertight test), on random rays, rays ending just before or
// just after a triangle, starting just past one, and aimed exactly at shared edges and vertices; and
// against each backend's own closest-hit query, ray by ray; before and after deformation.
#include "rt/ray_tracer.h"
#include "backends/registry.h"

#include "accel/builders/builder.h"
#include "accel/traverse.h"
#include "rt/instance_subset_tracer.h"
#include "rt/ray_tracer_check.h"
#include "rt/reflection_rays.h"
#include "rt/scene_geometry.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace glint::rt {
namespace {

using testing::brute_force_hits;
using testing::brute_force_occluded;
using testing::compare_occluded;
using testing::hit_exists;
using testing::occlusion_test_rays;
using testing::random_rays;
using testing::trace;
using testing::trace_occluded;

// One configuration of a CPU backend: which backend, which BLAS builder, which traversal.
struct CpuConfig {
  std::string_view backend;
  AccelOptions options;
  std::string label;
};

std::vector<CpuConfig> every_cpu_config() {
  std::vector<CpuConfig> configs;
  configs.push_back({"embree", {}, "embree"});
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    for (bool wide : {true, false}) {
      AccelOptions options;
      options.builder = builder;
      options.wide_traversal = wide;
      configs.push_back({"cpu", options, fmt::format("cpu {} {}", accel::builder_name(builder), wide ? "wide" : "binary")});
    }
  }
  return configs;
}

size_t count_ones(std::span<const uint8_t> flags) {
  size_t count = 0;
  for (uint8_t flag : flags) count += flag;
  return count;
}

TEST(RayTracerOcclusion, EveryCpuBackendBuilderAndTraversalEqualsBruteForce) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 1500, 7);
  const std::vector<uint8_t> expected = brute_force_occluded(scene, rays);
  // Both answers must be common, or the comparison proves little.
  ASSERT_GT(count_ones(expected), rays.size() / 4);
  ASSERT_LT(count_ones(expected), rays.size() * 3 / 4);
  for (const CpuConfig& config : every_cpu_config()) {
    const auto tracer = backends::make_ray_tracer(config.backend);
    tracer->build(scene, config.options);
    const std::vector<uint8_t> occluded = trace_occluded(*tracer, rays);
    EXPECT_EQ(compare_occluded(rays, expected, occluded), "") << config.label;
    // The same answer as the backend's own closest-hit query, ray by ray.
    EXPECT_EQ(compare_occluded(rays, hit_exists(trace(*tracer, rays)), occluded), "") << config.label << " vs closest";
  }
}

// The interval probes on their own: each hit's ray cut just before it (it must then depend on what
// lies in front), just after it (occluded) and started just past it (what lies behind).
TEST(RayTracerOcclusion, RaysEndingBeforeOrStartingPastAHitAreDecidedByTheInterval) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<accel::Ray> rays = random_rays(scene, 2000, 31);
  const std::vector<accel::Hit> hits = brute_force_hits(scene, rays);
  const std::vector<accel::Ray> probes = testing::hit_interval_probe_rays(rays, hits);
  const std::vector<uint8_t> expected = brute_force_occluded(scene, probes);
  // The probes are built in threes per hit (before, after, past) for rays starting at t_min 0 with
  // a hit t > 0: "after" must be occluded, and many "before"/"past" ones must not be.
  ASSERT_EQ(probes.size() % 3, 0u);
  size_t free_before = 0, free_past = 0;
  for (size_t i = 0; i < probes.size(); i += 3) {
    ASSERT_EQ(expected[i + 1], 1) << "probe " << i + 1 << " ends just after its hit";
    free_before += expected[i] == 0 ? 1 : 0;
    free_past += expected[i + 2] == 0 ? 1 : 0;
  }
  EXPECT_GT(free_before, probes.size() / 6);
  EXPECT_GT(free_past, probes.size() / 30);
  for (const CpuConfig& config : every_cpu_config()) {
    const auto tracer = backends::make_ray_tracer(config.backend);
    tracer->build(scene, config.options);
    EXPECT_EQ(compare_occluded(probes, expected, trace_occluded(*tracer, probes)), "") << config.label;
  }
}

// Watertightness: a ray aimed exactly at a shared edge or vertex inside a mesh passes through the
// surface there, so it must be occluded, in world space (brute force) and in every backend's object
// space. On the instanced scene (rotated, skewed and scaled instances) and the reduced atrium.
TEST(RayTracerOcclusion, RaysAimedAtSharedEdgesAndVerticesAreAlwaysOccluded) {
  for (const Scene& scene : {testing::make_instanced_scene(), testing::make_reduced_atrium()}) {
    const std::vector<accel::Ray> rays = testing::edge_and_vertex_rays(scene, 1500, 5);
    ASSERT_GT(rays.size(), 500u) << scene.name;
    const std::vector<uint8_t> all(rays.size(), 1);
    ASSERT_EQ(compare_occluded(rays, all, brute_force_occluded(scene, rays)), "") << scene.name << " brute force";
    for (const CpuConfig& config : every_cpu_config()) {
      const auto tracer = backends::make_ray_tracer(config.backend);
      tracer->build(scene, config.options);
      EXPECT_EQ(compare_occluded(rays, all, trace_occluded(*tracer, rays)), "") << scene.name << " " << config.label;
    }
  }
}

// Reflection-like rays on the reduced atrium (what the renderer's rays look like), against each
// backend's closest hits and, for a subset, brute force.
TEST(RayTracerOcclusion, ReflectionRaysOnReducedAtriumAgreeWithClosestHits) {
  const Scene scene = testing::make_reduced_atrium();
  std::vector<accel::Ray> rays = testing::reflection_like_rays(scene, 20000, 21);
  for (size_t i = 0; i < rays.size(); i += 3) rays[i].t_max = 2.0f;  // short shadow-like segments too
  const std::span<const accel::Ray> checked(rays.data(), 500);
  const std::vector<uint8_t> expected = brute_force_occluded(scene, checked);
  for (const CpuConfig& config : every_cpu_config()) {
    if (config.options.builder == accel::BvhBuilder::none) continue;  // one leaf: slow on 20k rays, covered above
    const auto tracer = backends::make_ray_tracer(config.backend);
    tracer->build(scene, config.options);
    const std::vector<uint8_t> occluded = trace_occluded(*tracer, rays);
    const size_t ones = count_ones(occluded);
    EXPECT_GT(ones, rays.size() / 4) << config.label;
    EXPECT_LT(ones, rays.size()) << config.label;
    EXPECT_EQ(compare_occluded(rays, hit_exists(trace(*tracer, rays)), occluded), "") << config.label;
    EXPECT_EQ(compare_occluded(checked, expected, std::span<const uint8_t>(occluded.data(), checked.size())), "")
        << config.label;
  }
}

// After the deformable meshes moved: update() with every policy, two frames, then the occlusion of
// the deformed geometry (which must differ from the rest pose's for some rays).
TEST(RayTracerOcclusion, FollowsDeformationWithEveryUpdatePolicy) {
  for (const CpuConfig& config : every_cpu_config()) {
    const accel::BvhBuilder builder = config.options.builder;
    if (config.backend == "cpu" && builder != accel::BvhBuilder::sah && builder != accel::BvhBuilder::lbvh &&
        builder != accel::BvhBuilder::sbvh)
      continue;  // the update paths do not depend on the builder beyond refittable or not
    for (UpdatePolicy policy : kAllUpdatePolicies) {
      if (config.backend == "cpu" && builder == accel::BvhBuilder::sbvh && policy != UpdatePolicy::rebuild) continue;
      Scene scene = testing::make_instanced_scene();
      const auto tracer = backends::make_ray_tracer(config.backend);
      tracer->build(scene, config.options);
      const std::vector<accel::Ray> rays = occlusion_test_rays(scene, 800, 5);
      const std::vector<uint8_t> rest = brute_force_occluded(scene, rays);
      SceneDeformers deformers(scene);
      for (int frame : {17, 40}) {
        tracer->update(scene, deformers.apply(scene, frame), policy);
        const std::vector<uint8_t> expected = brute_force_occluded(scene, rays);
        ASSERT_NE(compare_occluded(rays, rest, expected), "") << "the deformation must change some answers";
        EXPECT_EQ(compare_occluded(rays, expected, trace_occluded(*tracer, rays)), "")
            << config.label << " " << update_policy_name(policy) << " frame " << frame;
      }
      // Rays at the deformed surface's own edges and vertices stay watertight after a refit.
      const std::vector<accel::Ray> edges = testing::edge_and_vertex_rays(scene, 300, 9);
      EXPECT_EQ(compare_occluded(edges, std::vector<uint8_t>(edges.size(), 1), trace_occluded(*tracer, edges)), "")
          << config.label << " " << update_policy_name(policy) << " edges after deformation";
    }
  }
}

TEST(RayTracerOcclusion, InstanceSubsetTracerAnswersForItsInstancesOnly) {
  const Scene scene = testing::make_instanced_scene();
  const std::vector<uint32_t> chosen = deformable_instances(scene);
  ASSERT_FALSE(chosen.empty());
  InstanceSubsetTracer tracer(backends::make_ray_tracer("cpu"), chosen);
  tracer.build(scene, {});
  const std::vector<accel::Ray> rays = occlusion_test_rays(tracer.subset_scene(), 1000, 3);
  const std::vector<uint8_t> expected = brute_force_occluded(tracer.subset_scene(), rays);
  const std::vector<uint8_t> occluded = trace_occluded(tracer, rays);
  EXPECT_EQ(compare_occluded(rays, expected, occluded), "");
  // Fewer rays are occluded than in the whole scene (the floor and walls are not there).
  EXPECT_LT(count_ones(occluded), count_ones(brute_force_occluded(scene, rays)));
}

TEST(RayTracerOcclusion, MisuseIsAClearError) {
  const Scene scene = testing::make_instanced_scene();
  for (const CpuConfig& config : every_cpu_config()) {
    const auto tracer = backends::make_ray_tracer(config.backend);
    const std::vector<accel::Ray> rays(3);
    std::vector<uint8_t> occluded(3);
    EXPECT_NE(testing::error_of([&] { tracer->trace_any(rays, occluded); }).find("trace_any() before build()"),
              std::string::npos)
        << config.label;
    tracer->build(scene, config.options);
    std::vector<uint8_t> too_few(2);
    EXPECT_NE(testing::error_of([&] { tracer->trace_any(rays, too_few); }).find("3 rays but room for 2 results"),
              std::string::npos)
        << config.label;
    tracer->trace_any({}, {});  // nothing to trace is fine
  }
}

// The any-hit switch of accel's traversal: with kAnyHit the walk ends at the first primitive hit,
// while the closest-hit walk goes on to the others the ray passes through.
TEST(RayTracerOcclusion, AnyHitTraversalStopsAtTheFirstHit) {
  // A stack of 64 parallel squares (two triangles each) along z, crossed by one ray along z.
  Mesh stack;
  for (int layer = 0; layer < 64; ++layer) {
    const float z = static_cast<float>(layer);
    const auto base = static_cast<uint32_t>(stack.positions.size());
    stack.positions.insert(stack.positions.end(), {vec3(-1, -1, z), vec3(1, -1, z), vec3(1, 1, z), vec3(-1, 1, z)});
    stack.indices.insert(stack.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  const accel::TriangleMesh mesh = accel::make_indexed_mesh(stack.positions, stack.indices);
  const accel::Bvh bvh = accel::build_bvh(accel::BvhBuilder::sah, mesh, {});
  const vec3 origin(0.1f, 0.2f, -1.0f), direction(0.0f, 0.0f, 1.0f);
  const accel::WatertightRay ray = accel::make_watertight_ray(origin, direction);
  const auto count_walk = [&](auto any_hit) {
    size_t hits = 0, visits_after_first_hit = 0;
    float t_max = accel::kInfinity;
    accel::traverse_bvh<decltype(any_hit)::value>(bvh.view(), origin, direction, 0.0f, t_max,
                                                  [&](uint32_t prim, float& t_limit) {
      if (hits > 0) ++visits_after_first_hit;
      accel::TriangleHit hit;
      if (!accel::intersect_triangle(ray, mesh.triangle(prim), 0.0f, t_limit, hit)) return false;
      ++hits;
      return true;  // t_limit kept: every layer counts as a hit
    });
    return std::pair{hits, visits_after_first_hit};
  };
  const auto [any_hits, any_after] = count_walk(std::true_type{});
  EXPECT_EQ(any_hits, 1u);
  EXPECT_EQ(any_after, 0u);
  const auto [all_hits, all_after] = count_walk(std::false_type{});
  EXPECT_EQ(all_hits, 64u);
  EXPECT_GT(all_after, 0u);
  EXPECT_TRUE(accel::trace_any(bvh.view(), mesh, accel::Ray{origin, 0.0f, direction, accel::kInfinity}));
  EXPECT_FALSE(accel::trace_any(bvh.view(), mesh, accel::Ray{origin, 0.0f, direction, 0.5f}));
  EXPECT_TRUE(accel::trace_any(bvh.view(), mesh, accel::Ray{origin, 62.5f, direction, 63.5f}));
}

}  // namespace
}  // namespace glint::rt
