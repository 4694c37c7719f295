#include "accel/builders/build_sah.h"
#include "accel/builders/build_sbvh.h"
#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/bvh_validate.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/refit.h"
#include "accel/trace.h"
#include "core/error.h"
#include "scene/presets.h"
#include "accel/test_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace glint::accel {
namespace {

using testing::TestMesh;

// A few instances of the built-in atrium-simple in world space (~50k triangles): the walls, the
// beams and one armadillo, i.e. long architectural triangles next to small detail, where spatial
// splits matter. (The floor alone would be 53k tiles that no split can improve.)
TestMesh reduced_atrium() {
  const Scene scene = make_preset("atrium-simple");
  TestMesh flat;
  for (const glint::Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    if (mesh.name != "walls" && mesh.name != "beams" && mesh.name != "armadillo-0") continue;
    const auto base = static_cast<uint32_t>(flat.positions.size());
    for (const vec3& p : mesh.positions) flat.positions.push_back(vec3(instance.transform * vec4(p, 1.0f)));
    for (uint32_t index : mesh.indices) flat.indices.push_back(base + index);
  }
  return flat;
}

// A soup whose huge triangles straddle everything: spatial splits pay off there.
TestMesh long_triangles(uint32_t seed) {
  TestMesh mesh = testing::make_random_soup(seed, 2000);
  mesh.add_triangle(vec3(-3, -3, 0.1f), vec3(3, -3, 0.2f), vec3(0, 3, -0.1f));
  mesh.add_triangle(vec3(-3, 0.3f, -3), vec3(3, 0.2f, -3), vec3(0, -0.1f, 3));
  return mesh;
}

void check_sbvh(const Bvh& bvh, const TriangleMesh& mesh, const BuildOptions& options, const SbvhOptions& sbvh) {
  const PrimitiveBounds bounds = triangle_bounds(mesh);
  EXPECT_FALSE(bvh.refittable);
  EXPECT_EQ(bvh.builder, "sbvh");
  // Structure, leaf sizes, child boxes inside parents, every primitive at least once.
  EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, options.max_leaf_size));
  // Budget and coverage of every triangle by its leaves' boxes.
  EXPECT_NO_THROW(validate_sbvh_references(bvh, mesh, sbvh.reference_budget));
  EXPECT_GE(bvh.prim_indices.size(), mesh.triangle_count);
}

TEST(SbvhBuild, InvariantsAndBudgetOnEveryScene) {
  const TestMesh scenes[] = {testing::make_random_soup(1, 3000), testing::make_grid(20, false),
                             testing::make_grid(9, true),        testing::make_clustered(2, 4000),
                             long_triangles(3),                  testing::make_random_soup(4, 1),
                             testing::make_random_soup(5, 9)};
  for (const TestMesh& scene : scenes) {
    const TriangleMesh mesh = scene.view();
    for (uint32_t leaf : {1u, 4u}) {
      for (float budget : {1.0f, 1.1f, 2.0f}) {
        for (float alpha : {0.0f, 1e-5f}) {
          BuildOptions options;
          options.max_leaf_size = leaf;
          options.parallel_threshold = 256;  // exercise the TBB tasks and parallel binning
          SbvhOptions sbvh;
          sbvh.reference_budget = budget;
          sbvh.alpha = alpha;
          SCOPED_TRACE(::testing::Message() << scene.triangle_count() << " triangles, leaf " << leaf << ", budget "
                                            << budget << ", alpha " << alpha);
          check_sbvh(build_sbvh(mesh, options, sbvh), mesh, options, sbvh);
        }
      }
    }
  }
}

TEST(SbvhBuild, SpatialSplitsHappenWithinBudgetAndNotWithoutOne) {
  const TestMesh scene = long_triangles(7);
  const TriangleMesh mesh = scene.view();
  SbvhOptions sbvh;
  sbvh.alpha = 0.0f;
  const Bvh split = build_sbvh(mesh, {}, sbvh);
  EXPECT_GT(split.prim_indices.size(), mesh.triangle_count);  // some references were duplicated
  EXPECT_LE(split.prim_indices.size(), 2u * mesh.triangle_count);
  sbvh.reference_budget = 1.0f;
  const Bvh no_budget = build_sbvh(mesh, {}, sbvh);
  EXPECT_EQ(no_budget.prim_indices.size(), mesh.triangle_count);
  sbvh.reference_budget = 1.25f;
  const Bvh small_budget = build_sbvh(mesh, {}, sbvh);
  EXPECT_LE(small_budget.prim_indices.size(), mesh.triangle_count + mesh.triangle_count / 4);
  // alpha = 1: spatial splits only where no object split exists (all centroids equal).
  sbvh.reference_budget = 2.0f;
  sbvh.alpha = 1.0f;
  EXPECT_LT(build_sbvh(mesh, {}, sbvh).prim_indices.size(), split.prim_indices.size());
}

TEST(SbvhBuild, SahCostAtMostBinnedSahOnClusteredScenes) {
  // Compact clusters leave spatial splits little to do (a few dozen extra references at most), so
  // SBVH and SAH differ by noise there and greedy top-down choices that are cheaper locally can
  // end up a hair worse globally (seed 11: +0.01 %). Asserted: never measurably worse on any seed,
  // at most SAH over all seeds together.
  double sbvh_total = 0.0, sah_total = 0.0;
  for (uint32_t seed = 11; seed <= 20; ++seed) {
    const TestMesh scene = testing::make_clustered(seed, 20000);
    const TriangleMesh mesh = scene.view();
    const BvhStats sah = compute_stats(build_bvh(BvhBuilder::sah, mesh));
    const Bvh sbvh_bvh = build_sbvh(mesh);
    const BvhStats sbvh = compute_stats(sbvh_bvh);
    EXPECT_LE(sbvh.sah_cost, sah.sah_cost * (1.0 + 1e-3)) << "seed " << seed;
    sbvh_total += sbvh.sah_cost;
    sah_total += sah.sah_cost;
    std::printf("[ stats    ] clustered seed %u: %u triangles, %zu references, SAH %.6f (sbvh) vs %.6f (sah)\n", seed,
                mesh.triangle_count, sbvh_bvh.prim_indices.size(), sbvh.sah_cost, sah.sah_cost);
  }
  EXPECT_LE(sbvh_total, sah_total);
}

TEST(SbvhBuild, SahCostClearlyBelowBinnedSahWhereTrianglesStraddle) {
  // The random soup's huge and axis-aligned triangles overlap everything: spatial splits pay.
  const TestMesh scene = long_triangles(23);
  const TriangleMesh mesh = scene.view();
  const BvhStats sah = compute_stats(build_bvh(BvhBuilder::sah, mesh));
  const Bvh sbvh_bvh = build_sbvh(mesh);
  const BvhStats sbvh = compute_stats(sbvh_bvh);
  EXPECT_LT(sbvh.sah_cost, 0.9 * sah.sah_cost);
  std::printf("[ stats    ] straddling soup: %u triangles, %zu references, SAH %.4f (sbvh) vs %.4f (sah)\n",
              mesh.triangle_count, sbvh_bvh.prim_indices.size(), sbvh.sah_cost, sah.sah_cost);
}

TEST(SbvhBuild, SahCostAtMostBinnedSahOnReducedAtrium) {
  const TestMesh atrium = reduced_atrium();
  ASSERT_GE(atrium.triangle_count(), 40000u);  // the preset changed if this fails
  const TriangleMesh mesh = atrium.view();
  const BvhStats sah = compute_stats(build_bvh(BvhBuilder::sah, mesh));
  const BuildOptions options;
  const SbvhOptions sbvh_options;
  const Bvh sbvh_bvh = build_sbvh(mesh, options, sbvh_options);
  check_sbvh(sbvh_bvh, mesh, options, sbvh_options);
  const BvhStats sbvh = compute_stats(sbvh_bvh);
  EXPECT_LE(sbvh.sah_cost, sah.sah_cost);
  EXPECT_GT(sbvh_bvh.prim_indices.size(), mesh.triangle_count);  // walls and floors get split
  std::printf("[ stats    ] reduced atrium: %u triangles, %zu references, SAH %.6f (sbvh) vs %.6f (sah)\n",
              mesh.triangle_count, sbvh_bvh.prim_indices.size(), sbvh.sah_cost, sah.sah_cost);
}

TEST(SbvhBuild, BoxClippingWithoutGeometryIsValidAndTracesCorrectly) {
  // build_bvh(sbvh, BuildInput) has no triangles: references are clipped as boxes.
  const TestMesh scene = long_triangles(17);
  const TriangleMesh mesh = scene.view();
  const PrimitiveBounds bounds = triangle_bounds(mesh);
  BuildOptions options;
  options.max_leaf_size = 2;
  SbvhOptions sbvh;
  sbvh.alpha = 0.0f;
  const Bvh boxed = build_sbvh(bounds.input(), options, sbvh);
  EXPECT_NO_THROW(validate_bvh(boxed, bounds.boxes, 2));
  EXPECT_NO_THROW(validate_sbvh_references(boxed, mesh, sbvh.reference_budget));
  EXPECT_GT(boxed.prim_indices.size(), mesh.triangle_count);
  const Bvh dispatched = build_bvh(BvhBuilder::sbvh, bounds.input());
  EXPECT_NO_THROW(validate_bvh(dispatched, bounds.boxes, BuildOptions{}.max_leaf_size));

  const std::vector<Ray> rays = testing::make_random_rays(scene, 18, 5000);
  std::vector<Hit> hits(rays.size());
  trace_closest(boxed, mesh, rays, hits);
  for (size_t i = 0; i < rays.size(); ++i)
    ASSERT_TRUE(testing::same_closest_hit(testing::brute_force_closest(mesh, rays[i]), hits[i])) << "ray " << i;
}

TEST(SbvhBuild, RefitIsAClearError) {
  const TestMesh scene = long_triangles(19);
  Bvh bvh = build_bvh(BvhBuilder::sbvh, scene.view());
  try {
    refit(bvh, scene.view());
    FAIL() << "refit of an SBVH did not throw";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not refittable"), std::string::npos) << error.what();
  }
}

TEST(SbvhBuild, BadOptionsAndInputAreClearErrors) {
  const TestMesh scene = testing::make_random_soup(21, 50);
  const TriangleMesh mesh = scene.view();
  SbvhOptions sbvh;
  sbvh.reference_budget = 0.5f;
  EXPECT_THROW(build_sbvh(mesh, {}, sbvh), Error);
  sbvh = {};
  sbvh.spatial_bins = 1;
  EXPECT_THROW(build_sbvh(mesh, {}, sbvh), Error);
  sbvh = {};
  sbvh.alpha = -1.0f;
  EXPECT_THROW(build_sbvh(mesh, {}, sbvh), Error);
  BuildOptions options;
  options.max_leaf_size = 0;
  EXPECT_THROW(build_sbvh(mesh, options), Error);
  const std::vector<Aabb> boxes(3, Aabb{vec3(0), vec3(1)});
  const std::vector<vec3> centroids(2, vec3(0.5f));
  EXPECT_THROW(build_sbvh(BuildInput{boxes, centroids}), Error);
  EXPECT_EQ(parse_bvh_builder("sbvh"), BvhBuilder::sbvh);

  // A reference BVH traced against a mesh with fewer triangles than it references.
  const Bvh bvh = build_sbvh(mesh);
  const TestMesh smaller = testing::make_random_soup(22, 20);
  std::vector<Ray> rays(2);
  std::vector<Hit> hits(2);
  EXPECT_THROW(trace_closest(bvh, smaller.view(), rays, hits), Error);
}

TEST(SbvhBuild, EmptyMeshGivesAnEmptyBvh) {
  const TestMesh empty;
  const Bvh bvh = build_sbvh(empty.view());
  EXPECT_TRUE(bvh.nodes.empty());
  EXPECT_TRUE(bvh.prim_indices.empty());
  EXPECT_EQ(bvh.depth, 0u);
}

}  // namespace
}  // namespace glint::accel
