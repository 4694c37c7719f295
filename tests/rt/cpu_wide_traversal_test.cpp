// The cpu backend's 8-wide traversal (AccelOptions::wide_traversal) against its binary traversal on
// the same rays: identical hits (instance, triangle, t) for every builder (sbvh through the binary
// fallback), before and after every kind of update, on random and reflection-like rays; and the
// two-level wide batch's own checks.
#include "rt/cpu_ray_tracer.h"

#include "accel/builders/builder.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "rt/ray_tracer_check.h"
#include "rt/reflection_rays.h"
#include "rt/tiny_scene.h"
#include "rt/wide_two_level_trace.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace glint::rt {
namespace {

using testing::brute_force_hits;
using testing::compare_hits;
using testing::random_rays;
using testing::reflection_like_rays;
using testing::trace;

// "" when both traversals found the same thing for every ray: same hit or miss, same instance and
// triangle, t within 1e-5 relative. Otherwise the first few differences.
std::string compare_identical(std::span<const accel::Hit> binary, std::span<const accel::Hit> wide) {
  std::string report;
  int reported = 0;
  for (size_t i = 0; i < binary.size() && reported < 5; ++i) {
    const accel::Hit& a = binary[i];
    const accel::Hit& b = wide[i];
    const bool same = a.valid() == b.valid() &&
                      (!a.valid() || (a.instance == b.instance && a.prim == b.prim &&
                                      std::abs(a.t - b.t) <= 1e-5f * std::max(1.0f, std::abs(a.t))));
    if (same) continue;
    report += fmt::format("ray {}: binary (instance {}, prim {}, t {}) wide (instance {}, prim {}, t {}); ", i,
                          a.instance, a.prim, a.t, b.instance, b.prim, b.t);
    ++reported;
  }
  return report;
}

size_t hit_count(std::span<const accel::Hit> hits) {
  return static_cast<size_t>(std::count_if(hits.begin(), hits.end(), [](const accel::Hit& hit) { return hit.valid(); }));
}

std::vector<accel::Ray> mixed_rays(const Scene& scene, size_t count, uint32_t seed) {
  std::vector<accel::Ray> rays = random_rays(scene, count / 2, seed);
  const std::vector<accel::Ray> reflected = reflection_like_rays(scene, count - count / 2, seed + 1);
  rays.insert(rays.end(), reflected.begin(), reflected.end());
  return rays;
}

// The binary and the wide cpu tracer over one scene, built with the same options.
struct TracerPair {
  CpuRayTracer binary;
  CpuRayTracer wide;

  void build(const Scene& scene, AccelOptions options) {
    options.wide_traversal = false;
    binary.build(scene, options);
    options.wide_traversal = true;
    wide.build(scene, options);
  }
  void update(const Scene& scene, std::span<const uint32_t> dirty, UpdatePolicy policy) {
    binary.update(scene, dirty, policy);
    wide.update(scene, dirty, policy);
  }
  // Both traces of `rays` (the first `random_count` of them from random_rays); expects them
  // identical, and the random ones equal to brute force too. The reflection-like rays start on a
  // surface, where the world-space brute force and the object-space traversal may round a grazing
  // neighbour triangle differently, so only the two traversals are compared on them.
  void expect_identical(const Scene& scene, std::span<const accel::Ray> rays, size_t random_count,
                        const std::string& what) const {
    const std::vector<accel::Hit> binary_hits = trace(binary, rays);
    const std::vector<accel::Hit> wide_hits = trace(wide, rays);
    EXPECT_GT(hit_count(binary_hits), rays.size() / 4) << what << ": the rays must mostly hit something";
    EXPECT_EQ(compare_identical(binary_hits, wide_hits), "") << what;
    const std::span<const accel::Ray> random = rays.first(random_count);
    EXPECT_EQ(compare_hits(scene, random, brute_force_hits(scene, random), std::span(wide_hits).first(random_count)), "")
        << what;
  }
};

bool refittable(accel::BvhBuilder builder) { return builder != accel::BvhBuilder::sbvh; }

TEST(CpuWideTraversal, EqualsBinaryForEveryBuilder) {
  const Scene scene = testing::make_instanced_scene(16);
  const std::vector<accel::Ray> rays = mixed_rays(scene, 3000, 31);
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    TracerPair pair;
    AccelOptions options;
    options.builder = builder;
    pair.build(scene, options);
    pair.expect_identical(scene, rays, 1500, std::string(accel::builder_name(builder)));
    // The wide nodes are counted; sbvh's BVHs cannot be collapsed, so it holds none (binary fallback).
    const uint64_t binary_bytes = pair.binary.stats().memory_bytes;
    const uint64_t wide_bytes = pair.wide.stats().memory_bytes;
    if (refittable(builder)) {
      EXPECT_GE(wide_bytes, binary_bytes + scene.meshes.size() * sizeof(accel::WideNode<8>))
          << accel::builder_name(builder);
    } else {
      EXPECT_EQ(wide_bytes, binary_bytes) << accel::builder_name(builder);
    }
  }
}

// mixed_rays(scene, count, seed): count / 2 random rays, then reflection-like ones.

// Two frames of deformation, each followed by `policy` on both tracers, then identical hits.
void check_updates(accel::BvhBuilder builder, UpdatePolicy policy, float auto_ratio) {
  Scene scene = testing::make_instanced_scene(16);
  SineDeform& wave = *scene.meshes[2].deform;  // strong enough that a refit visibly degrades
  wave.amplitude = 1.0f;
  wave.frequency = 25.0f;
  TracerPair pair;
  AccelOptions options;
  options.builder = builder;
  options.auto_rebuild_sah_ratio = auto_ratio;
  pair.build(scene, options);
  SceneDeformers deformers(scene);
  const std::string what = fmt::format("{} {} ratio {}", accel::builder_name(builder), update_policy_name(policy), auto_ratio);
  for (int frame : {13, 40}) {
    const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
    ASSERT_FALSE(dirty.empty());
    pair.update(scene, dirty, policy);
    // Fresh rays from the deformed surfaces: the reflection rays start on the moved sheet too.
    pair.expect_identical(scene, mixed_rays(scene, 1500, static_cast<uint32_t>(frame)), 750,
                          what + fmt::format(" frame {}", frame));
  }
  const RayTracerStats binary = pair.binary.stats();
  const RayTracerStats wide = pair.wide.stats();
  EXPECT_EQ(wide.rebuilds, binary.rebuilds) << what;
  EXPECT_EQ(wide.refits, binary.refits) << what;
  EXPECT_EQ(wide.blas_sah_drift, binary.blas_sah_drift) << what << ": the drift is the binary BVH's in both";
}

TEST(CpuWideTraversal, EqualsBinaryAfterUpdatesForEveryRefittableBuilder) {
  for (accel::BvhBuilder builder : accel::kAllBvhBuilders) {
    if (!refittable(builder)) continue;
    check_updates(builder, UpdatePolicy::rebuild, 1.3f);
    check_updates(builder, UpdatePolicy::refit, 1.3f);
    check_updates(builder, UpdatePolicy::automatic, 1.0f);     // rebuilds every time
    check_updates(builder, UpdatePolicy::automatic, 1000.0f);  // refits every time
  }
}

TEST(CpuWideTraversal, SbvhFallsBackToBinaryAndRebuildsStayIdentical) {
  check_updates(accel::BvhBuilder::sbvh, UpdatePolicy::rebuild, 1.3f);
}

TEST(CpuWideTraversal, AutomaticPolicyDecidesAsTheBinaryOneDoes) {
  // The default threshold on the strong wave: whatever it decides, it decides it from the binary
  // BVH's SAH, so both tracers count the same rebuilds and refits (checked in check_updates).
  check_updates(accel::BvhBuilder::sah, UpdatePolicy::automatic, 1.3f);
  check_updates(accel::BvhBuilder::lbvh, UpdatePolicy::automatic, 1.3f);
}

TEST(CpuWideTraversal, EqualsBinaryOnTheDeformingReducedAtrium) {
  Scene scene = testing::make_reduced_atrium();
  TracerPair pair;
  pair.build(scene, {});
  const std::vector<accel::Ray> rest_rays = reflection_like_rays(scene, 600, 2);
  {
    const std::vector<accel::Hit> binary_hits = trace(pair.binary, rest_rays);
    EXPECT_GT(hit_count(binary_hits), rest_rays.size() / 4);  // open to the sky: about 40 % hit
    EXPECT_EQ(compare_identical(binary_hits, trace(pair.wide, rest_rays)), "");
  }
  SceneDeformers deformers(scene);
  for (UpdatePolicy policy : kAllUpdatePolicies) {
    const std::vector<uint32_t> dirty = deformers.apply(scene, 20 + 10 * static_cast<int>(policy));
    pair.update(scene, dirty, policy);
    const std::vector<accel::Ray> rays = reflection_like_rays(scene, 600, 3);
    const std::vector<accel::Hit> binary_hits = trace(pair.binary, rays);
    EXPECT_GT(hit_count(binary_hits), rays.size() / 4);
    EXPECT_EQ(compare_identical(binary_hits, trace(pair.wide, rays)), "") << update_policy_name(policy);
  }
}

TEST(CpuWideTraversal, EqualTAcrossInstancesKeepsTheBinaryTraversalsChoice) {
  // Every instance drawn twice at the same place: each hit is an exact tie between two instances.
  // The binary walk keeps the first one it found; the wide one must pick the same instance.
  Scene scene = testing::make_instanced_scene();
  const size_t original = scene.instances.size();
  for (size_t i = 0; i < original; ++i) scene.instances.push_back(scene.instances[i]);
  TracerPair pair;
  pair.build(scene, {});
  const std::vector<accel::Ray> rays = mixed_rays(scene, 2000, 8);
  const std::vector<accel::Hit> binary_hits = trace(pair.binary, rays);
  const std::vector<accel::Hit> wide_hits = trace(pair.wide, rays);
  EXPECT_GT(hit_count(binary_hits), rays.size() / 4);
  EXPECT_EQ(compare_identical(binary_hits, wide_hits), "");
}

TEST(CpuWideTraversal, TwoLevelWideBatchRejectsMismatchedInputs) {
  const Scene scene = testing::make_tiny_scene();
  std::vector<accel::Bvh> bvhs;
  std::vector<accel::Blas> blases;
  bvhs.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    const accel::TriangleMesh view = accel::make_indexed_mesh(mesh.positions, mesh.indices);
    bvhs.push_back(accel::build_bvh(accel::BvhBuilder::sah, view));
    blases.push_back(accel::make_blas(bvhs.back(), view));
  }
  std::vector<accel::Instance> instances;
  for (const Instance& instance : scene.instances) instances.push_back(accel::make_instance(instance.mesh, instance.transform));
  const accel::Tlas tlas = accel::build_tlas(blases, instances, accel::BvhBuilder::sah);
  std::vector<accel::Ray> rays(4);
  std::vector<accel::Hit> hits(4);

  const std::vector<const accel::WideBvh8*> too_few(blases.size() - 1, nullptr);
  EXPECT_NE(testing::error_of([&] { trace_closest_wide(tlas, blases, too_few, rays, hits); }).find("wide BVHs for"),
            std::string::npos);
  std::vector<accel::Hit> short_hits(3);
  const std::vector<const accel::WideBvh8*> none(blases.size(), nullptr);
  (void)testing::error_of([&] { trace_closest_wide(tlas, blases, none, rays, short_hits); });
  // The floor's wide BVH handed in for the sheet (another triangle count).
  const accel::WideBvh8 floor_wide = accel::collapse_to_wide<8>(bvhs[0], blases[0].mesh);
  std::vector<const accel::WideBvh8*> swapped(blases.size(), nullptr);
  swapped[2] = &floor_wide;
  EXPECT_NE(testing::error_of([&] { trace_closest_wide(tlas, blases, swapped, rays, hits); }).find("wide BVH 2"),
            std::string::npos);
}

}  // namespace
}  // namespace glint::rt
