#include "accel/builders/build_median.h"
#include "accel/builders/build_none.h"
#include "accel/builders/build_sah.h"
#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/bvh_validate.h"
#include "accel/builders/primitive_bounds.h"
#include "core/error.h"
#include "accel/test_scenes.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using BuildParam = std::tuple<BvhBuilder, uint32_t>;  // builder, max_leaf_size

std::string build_param_name(const ::testing::TestParamInfo<BuildParam>& info) {
  return std::string(builder_name(std::get<0>(info.param))) + "_leaf" + std::to_string(std::get<1>(info.param));
}

uint32_t effective_leaf_limit(BvhBuilder builder, uint32_t max_leaf_size, size_t prim_count) {
  return builder == BvhBuilder::none ? static_cast<uint32_t>(prim_count) : max_leaf_size;
}

class BvhBuild : public ::testing::TestWithParam<BuildParam> {};

TEST_P(BvhBuild, InvariantsHoldOnEveryScene) {
  const auto [builder, leaf_size] = GetParam();
  BuildOptions options;
  options.max_leaf_size = leaf_size;
  options.parallel_threshold = 256;  // exercise the TBB tasks on test-sized inputs
  const testing::TestMesh scenes[] = {testing::make_random_soup(1, 3000), testing::make_grid(20, false),
                                      testing::make_grid(9, true), testing::make_clustered(2, 4000),
                                      testing::make_random_soup(3, 1), testing::make_random_soup(4, 9)};
  for (const testing::TestMesh& scene : scenes) {
    const PrimitiveBounds bounds = triangle_bounds(scene.view());
    const Bvh bvh = build_bvh(builder, bounds.input(), options);
    EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, effective_leaf_limit(builder, leaf_size, bounds.boxes.size())))
        << scene.triangle_count() << " triangles";
    EXPECT_EQ(bvh.builder, builder_name(builder));
    EXPECT_EQ(bvh.refittable, builder != BvhBuilder::sbvh);  // spatial splits duplicate references
    const BvhStats stats = compute_stats(bvh);
    EXPECT_EQ(stats.nodes, bvh.nodes.size());
    EXPECT_EQ(stats.leaves, stats.interior_nodes + 1);
    EXPECT_EQ(stats.max_depth, bvh.depth);
    EXPECT_EQ(stats.memory_bytes, bvh.nodes.size() * 32 + bvh.prim_indices.size() * 4);
    EXPECT_GE(stats.sah_cost, 0.0);
  }
}

TEST_P(BvhBuild, SameInputGivesTheSameArrays) {
  const auto [builder, leaf_size] = GetParam();
  BuildOptions options;
  options.max_leaf_size = leaf_size;
  options.parallel_threshold = 64;
  const testing::TestMesh scene = testing::make_clustered(5, 20000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  const Bvh a = build_bvh(builder, bounds.input(), options);
  const Bvh b = build_bvh(builder, bounds.input(), options);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(BvhNode)));
  EXPECT_EQ(a.prim_indices, b.prim_indices);
}

INSTANTIATE_TEST_SUITE_P(Accel, BvhBuild,
                         ::testing::Combine(::testing::ValuesIn(kAllBvhBuilders), ::testing::Values(1u, 4u, 8u)),
                         build_param_name);

TEST(BvhBuilders, EmptyInputGivesAnEmptyBvh) {
  for (BvhBuilder builder : kAllBvhBuilders) {
    const Bvh bvh = build_bvh(builder, BuildInput{});
    EXPECT_TRUE(bvh.nodes.empty());
    EXPECT_TRUE(bvh.prim_indices.empty());
    EXPECT_EQ(bvh.depth, 0u);
    EXPECT_NO_THROW(validate_bvh(bvh, {}, 4));
  }
}

TEST(BvhBuilders, NoneIsOneLeafOverEverything) {
  const testing::TestMesh scene = testing::make_random_soup(9, 100);
  const Bvh bvh = build_bvh(BvhBuilder::none, scene.view());
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_EQ(bvh.nodes[0].prim_count, 100u);
  EXPECT_EQ(bvh.depth, 1u);
}

TEST(BvhBuilders, BadInputIsAClearError) {
  const std::vector<Aabb> boxes(3, Aabb{vec3(0), vec3(1)});
  const std::vector<vec3> centroids(2, vec3(0.5f));
  for (BvhBuilder builder : kAllBvhBuilders)
    EXPECT_THROW(build_bvh(builder, BuildInput{boxes, centroids}), Error) << builder_name(builder);
  const std::vector<vec3> three(3, vec3(0.5f));
  BuildOptions options;
  options.bins = 1;
  EXPECT_THROW(build_sah(BuildInput{boxes, three}, options), Error);
  options.bins = 32;
  options.max_leaf_size = 0;
  EXPECT_THROW(build_median(BuildInput{boxes, three}, options), Error);
  EXPECT_THROW(parse_bvh_builder("kdtree-ish"), Error);
  EXPECT_EQ(parse_bvh_builder("sah"), BvhBuilder::sah);

  std::vector<vec3> positions{vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)};
  const std::vector<uint32_t> bad_indices{0, 1, 3};
  EXPECT_THROW(make_indexed_mesh(positions, bad_indices), Error);
  positions[1].x = std::numeric_limits<float>::quiet_NaN();
  const std::vector<uint32_t> indices{0, 1, 2};
  EXPECT_THROW(triangle_bounds(make_indexed_mesh(positions, indices)), Error);
}

TEST(BvhBuilders, IdenticalCentroidsStillSplitToLeafSize) {
  // All primitives at the same place: no SAH split exists, the builder must still respect
  // max_leaf_size (by splitting in index order) and stay shallow.
  const std::vector<Aabb> boxes(1000, Aabb{vec3(0), vec3(1)});
  const std::vector<vec3> centroids(1000, vec3(0.5f));
  for (BvhBuilder builder : {BvhBuilder::median, BvhBuilder::sah}) {
    const Bvh bvh = build_bvh(builder, BuildInput{boxes, centroids});
    EXPECT_NO_THROW(validate_bvh(bvh, boxes, 4));
    EXPECT_LE(bvh.depth, 10u);
  }
}

TEST(BvhBuilders, DepthStaysWithinTheTraversalLimitOnAdversarialInput) {
  // Geometrically shrinking primitives towards the origin: the SAH peels one off per level, which
  // would give a depth of about the primitive count without the depth guard.
  std::vector<Aabb> boxes;
  std::vector<vec3> centroids;
  float size = 1.0f;
  for (int i = 0; i < 2000; ++i) {
    boxes.push_back(Aabb{vec3(size), vec3(2.0f * size)});
    centroids.push_back(vec3(1.5f * size));
    size *= 0.97f;
  }
  BuildOptions options;
  options.max_leaf_size = 1;
  for (BvhBuilder builder : {BvhBuilder::median, BvhBuilder::sah}) {
    const Bvh bvh = build_bvh(builder, BuildInput{boxes, centroids}, options);
    EXPECT_NO_THROW(validate_bvh(bvh, boxes, 1));
    EXPECT_LE(bvh.depth, kMaxBvhDepth);
  }
}

TEST(BvhBuilders, SahCostOfSahIsAtMostMedianOnClusteredScenes) {
  for (uint32_t seed : {11u, 12u, 13u}) {
    const testing::TestMesh scene = testing::make_clustered(seed, 20000);
    const PrimitiveBounds bounds = triangle_bounds(scene.view());
    for (uint32_t bins : {16u, 32u}) {
      BuildOptions options;
      options.bins = bins;
      const BvhStats sah = compute_stats(build_sah(bounds.input(), options));
      const BvhStats median = compute_stats(build_median(bounds.input(), options));
      EXPECT_LE(sah.sah_cost, median.sah_cost) << "seed " << seed << ", " << bins << " bins";
      std::printf("[ stats    ] seed %u bins %u\n  %s\n  %s\n", seed, bins, format_stats("sah", sah).c_str(),
                  format_stats("median", median).c_str());
    }
  }
}

TEST(BvhStats, SahCostOfAHandMadeTree) {
  // Two unit cubes side by side, one primitive each: root half-area (2x1x1 box) = 2 + 1 + 2 = 5,
  // each leaf 3. Cost = (1.2 * 5 + 1 * (3 * 1 + 3 * 1)) / 5 = 2.4.
  const std::vector<Aabb> boxes{Aabb{vec3(0), vec3(1)}, Aabb{vec3(1, 0, 0), vec3(2, 1, 1)}};
  const std::vector<vec3> centroids{boxes[0].center(), boxes[1].center()};
  BuildOptions options;
  options.max_leaf_size = 1;
  const BvhStats stats = compute_stats(build_sah(BuildInput{boxes, centroids}, options));
  EXPECT_EQ(stats.nodes, 3u);
  EXPECT_EQ(stats.leaves, 2u);
  EXPECT_EQ(stats.max_depth, 2u);
  EXPECT_NEAR(stats.sah_cost, 2.4, 1e-6);
}

}  // namespace
}  // namespace glint::accel
