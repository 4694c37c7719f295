#include "accel/builders/builder.h"
#include "accel/bvh_validate.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/refit.h"
#include "accel/trace.h"
#include "core/error.h"
#include "test_scenes.h"

#include <gtest/gtest.h>

#include <random>

namespace glint::accel {
namespace {

// Every vertex jitters a little; one in ten jumps far (the refitted tree gets worse, never wrong).
void move_vertices(testing::TestMesh& mesh, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    const float amount = i % 10 == 0 ? 1.5f : 0.03f;
    mesh.positions[i] += amount * vec3(u(rng), u(rng), u(rng));
  }
}

TEST(Refit, MovedVerticesGiveTheSameHitsAsAFreshBuild) {
  const testing::TestMesh original = testing::make_random_soup(41, 2000);
  testing::TestMesh soup = original;
  move_vertices(soup, 42);
  const TriangleMesh moved = soup.view();
  const std::vector<Ray> rays = testing::make_random_rays(soup, 43, 10000);
  std::vector<Hit> expected(rays.size());
  for (size_t i = 0; i < rays.size(); ++i) expected[i] = testing::brute_force_closest(moved, rays[i]);
  const PrimitiveBounds bounds = triangle_bounds(moved);

  for (BvhBuilder builder : kAllBvhBuilders) {
    for (uint32_t leaf_size : {1u, 4u}) {
      BuildOptions options;
      options.max_leaf_size = leaf_size;
      Bvh refitted = build_bvh(builder, original.view(), options);
      if (!refitted.refittable) {  // spatial splits (sbvh): refit must refuse, not give wrong boxes
        EXPECT_THROW(refit(refitted, moved), Error) << builder_name(builder);
        continue;
      }
      refit(refitted, moved);
      const uint32_t leaf_limit = builder == BvhBuilder::none ? moved.triangle_count : leaf_size;
      EXPECT_NO_THROW(validate_bvh(refitted, bounds.boxes, leaf_limit)) << builder_name(builder);

      const Bvh fresh = build_bvh(builder, moved, options);
      std::vector<Hit> refit_hits(rays.size()), fresh_hits(rays.size());
      trace_closest(refitted, moved, rays, refit_hits);
      trace_closest(fresh, moved, rays, fresh_hits);
      std::vector<uint8_t> occluded(rays.size());
      trace_any(refitted, moved, rays, occluded);
      size_t failures = 0;
      for (size_t i = 0; i < rays.size() && failures < 10; ++i) {
        const auto refit_ok = testing::same_closest_hit(expected[i], refit_hits[i]);
        EXPECT_TRUE(refit_ok) << builder_name(builder) << " leaf " << leaf_size << " ray " << i;
        EXPECT_TRUE(testing::same_closest_hit(expected[i], fresh_hits[i])) << "ray " << i;
        EXPECT_EQ(occluded[i] != 0, expected[i].valid()) << "ray " << i;
        failures += refit_ok ? 0 : 1;
      }
    }
  }
}

TEST(Refit, KeepsTopologyAndUpdatesOnlyBoxes) {
  testing::TestMesh grid = testing::make_grid(16, false);
  Bvh bvh = build_bvh(BvhBuilder::sah, grid.view());
  const Bvh before = bvh;
  for (vec3& p : grid.positions) p.z += 0.25f * std::sin(p.x) * std::cos(p.y);
  refit(bvh, grid.view());
  ASSERT_EQ(bvh.nodes.size(), before.nodes.size());
  EXPECT_EQ(bvh.prim_indices, before.prim_indices);
  for (size_t i = 0; i < bvh.nodes.size(); ++i) {
    EXPECT_EQ(bvh.nodes[i].first, before.nodes[i].first);
    EXPECT_EQ(bvh.nodes[i].prim_count, before.nodes[i].prim_count);
  }
  EXPECT_GT(bvh.bounds().extent().z, 0.0f);  // the flat grid now has thickness
}

TEST(Refit, EveryBuildersLayoutIsRefittedInParallel) {
  // Subtrees with contiguous descendants, whichever child's come first (lbvh puts the right one's
  // first); a tree in neither order falls back to one serial sweep.
  const testing::TestMesh scene = testing::make_clustered(47, 20000);
  for (const BvhBuilder builder : kAllBvhBuilders) {
    if (builder == BvhBuilder::none || builder == BvhBuilder::sbvh) continue;
    const Bvh bvh = build_bvh(builder, scene.view());
    EXPECT_TRUE(detail::refits_in_parallel(bvh)) << builder_name(builder);
  }
  // Children after parents, but the left child's descendants (3, 4, 7, 8) around the right
  // child's (5, 6): refitted by one serial sweep, to the same boxes.
  Bvh interleaved;
  const auto interior = [](uint32_t first) { BvhNode n; n.first = first; return n; };
  const auto leaf = [](uint32_t prim) { BvhNode n; n.first = prim; n.prim_count = 1; return n; };
  for (const BvhNode& node : {interior(1), interior(3), interior(5), interior(7), leaf(0), leaf(3), leaf(4), leaf(1), leaf(2)})
    interleaved.nodes.push_back(node);
  for (uint32_t prim = 0; prim < 5; ++prim) interleaved.prim_indices.push_back(prim);
  interleaved.depth = 4;
  std::vector<Aabb> boxes;
  for (int prim = 0; prim < 5; ++prim) boxes.push_back(Aabb{vec3(float(prim), 0.0f, 0.0f), vec3(float(prim) + 0.5f, 1.0f, 1.0f)});
  EXPECT_FALSE(detail::refits_in_parallel(interleaved));
  refit(interleaved, boxes);
  EXPECT_EQ(interleaved.nodes[0].bounds_min, vec3(0.0f, 0.0f, 0.0f));
  EXPECT_EQ(interleaved.nodes[0].bounds_max, vec3(4.5f, 1.0f, 1.0f));
  EXPECT_EQ(interleaved.nodes[3].bounds_min, vec3(1.0f, 0.0f, 0.0f));  // prims 1 and 2
  EXPECT_EQ(interleaved.nodes[3].bounds_max, vec3(2.5f, 1.0f, 1.0f));
  EXPECT_NO_THROW(validate_bvh(interleaved, boxes, 1));
}

TEST(Refit, RefusesNonRefittableStructures) {
  const testing::TestMesh soup = testing::make_random_soup(44, 100);
  Bvh bvh = build_bvh(BvhBuilder::sah, soup.view());
  bvh.refittable = false;  // what a spatial-split builder (sbvh) will set
  EXPECT_THROW(refit(bvh, soup.view()), Error);
  try {
    refit(bvh, soup.view());
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not refittable"), std::string::npos) << error.what();
  }
}

TEST(Refit, WrongPrimitiveCountIsAClearError) {
  const testing::TestMesh soup = testing::make_random_soup(45, 100);
  const testing::TestMesh other = testing::make_random_soup(46, 101);
  Bvh bvh = build_bvh(BvhBuilder::median, soup.view());
  EXPECT_THROW(refit(bvh, other.view()), Error);
}

TEST(Refit, EmptyBvhIsANoOp) {
  const testing::TestMesh empty;
  Bvh bvh = build_bvh(BvhBuilder::sah, empty.view());
  EXPECT_NO_THROW(refit(bvh, empty.view()));
}

}  // namespace
}  // namespace glint::accel
