#include "accel/kdtree/kdtree.h"
#include "accel/kdtree/kdtree_stats.h"
#include "accel/kdtree/kdtree_trace.h"
#include "accel/kdtree/kdtree_validate.h"
#include "core/error.h"
#include "accel/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace glint::accel {
namespace {

using testing::TestMesh;

TEST(KdTreeBuild, InvariantsOnEveryScene) {
  const TestMesh scenes[] = {testing::make_random_soup(1, 3000), testing::make_grid(20, false),
                             testing::make_grid(9, true),        testing::make_clustered(2, 4000),
                             testing::make_random_soup(4, 1),    testing::make_random_soup(5, 9)};
  for (const TestMesh& scene : scenes) {
    const TriangleMesh mesh = scene.view();
    for (float intersection_cost : {0.5f, 1.5f, 20.0f}) {
      KdTreeOptions options;
      options.intersection_cost = intersection_cost;
      options.parallel_threshold = 256;  // exercise the TBB tasks
      SCOPED_TRACE(::testing::Message() << scene.triangle_count() << " triangles, K_I " << intersection_cost);
      const KdTree tree = build_kdtree(mesh, options);
      EXPECT_NO_THROW(validate_kdtree(tree, mesh, kdtree_depth_limit(mesh.triangle_count, options)));
      const KdTreeStats stats = compute_stats(tree);
      EXPECT_EQ(stats.nodes, tree.nodes.size());
      EXPECT_EQ(stats.leaves, stats.interior_nodes + 1);
      EXPECT_EQ(stats.max_depth, tree.depth);
      EXPECT_EQ(stats.references, tree.prim_indices.size());
      EXPECT_GE(stats.references, size_t{mesh.triangle_count});
      EXPECT_EQ(stats.memory_bytes, tree.nodes.size() * 8 + tree.prim_indices.size() * 4);
      EXPECT_GE(stats.sah_cost, 0.0);
    }
  }
}

TEST(KdTreeBuild, DepthLimitIsTheUsualFormulaAndIsHonoured) {
  KdTreeOptions options;
  EXPECT_EQ(kdtree_depth_limit(1, options), 8u);
  EXPECT_EQ(kdtree_depth_limit(1024, options), 21u);  // 8 + 1.3 * 10
  EXPECT_EQ(kdtree_depth_limit(1u << 30, options), 47u);
  options.max_depth = 3;
  EXPECT_EQ(kdtree_depth_limit(1024, options), 3u);
  options.max_depth = 1000;
  EXPECT_EQ(kdtree_depth_limit(1024, options), kMaxKdDepth);

  // A tight limit: the tree stops there, and is still correct.
  const TestMesh scene = testing::make_clustered(6, 5000);
  const TriangleMesh mesh = scene.view();
  options.max_depth = 4;
  const KdTree shallow = build_kdtree(mesh, options);
  EXPECT_LE(shallow.depth, 4u);
  EXPECT_NO_THROW(validate_kdtree(shallow, mesh, 4));
  const std::vector<Ray> rays = testing::make_random_rays(scene, 7, 2000);
  std::vector<Hit> hits(rays.size());
  trace_closest(shallow, mesh, rays, hits);
  for (size_t i = 0; i < rays.size(); ++i) {
    const Hit expected = testing::brute_force_closest(mesh, rays[i]);
    ASSERT_EQ(expected.valid(), hits[i].valid()) << "ray " << i;
    if (expected.valid()) {
      ASSERT_NEAR(hits[i].t, expected.t, 1e-4f * std::max(1.0f, expected.t)) << "ray " << i;
    }
  }
}

TEST(KdTreeBuild, CutsOffEmptySpaceAndSplitsStraddlersPerfectly) {
  // Two far-apart clusters: the empty gap between them must become (at least) one empty leaf, and
  // a triangle crossing a split plane is referenced on both sides.
  TestMesh scene = testing::make_random_soup(8, 500);
  TestMesh other = testing::make_random_soup(9, 500);
  const auto base = static_cast<uint32_t>(scene.positions.size());
  for (const vec3& p : other.positions) scene.positions.push_back(p + vec3(20.0f, 0.0f, 0.0f));
  for (uint32_t index : other.indices) scene.indices.push_back(base + index);
  const TriangleMesh mesh = scene.view();
  const KdTree tree = build_kdtree(mesh);
  const KdTreeStats stats = compute_stats(tree);
  EXPECT_GT(stats.empty_leaves, 0u);
  EXPECT_GT(stats.references, size_t{mesh.triangle_count});
  EXPECT_NO_THROW(validate_kdtree(tree, mesh, kdtree_depth_limit(mesh.triangle_count, {})));
  std::printf("[ stats    ] %s\n", format_stats("kdtree", stats).c_str());
}

TEST(KdTreeBuild, SameInputGivesTheSameArrays) {
  const TestMesh scene = testing::make_clustered(10, 20000);
  KdTreeOptions options;
  options.parallel_threshold = 64;
  const KdTree a = build_kdtree(scene.view(), options);
  const KdTree b = build_kdtree(scene.view(), options);
  ASSERT_EQ(a.nodes.size(), b.nodes.size());
  EXPECT_EQ(0, std::memcmp(a.nodes.data(), b.nodes.data(), a.nodes.size() * sizeof(KdNode)));
  EXPECT_EQ(a.prim_indices, b.prim_indices);
}

TEST(KdTreeBuild, HandMadeSplitAndStats) {
  // Two unit squares (two triangles each) far apart along x: the SAH splits between them and both
  // sides hold exactly their own two triangles.
  TestMesh scene;
  for (float x : {0.0f, 10.0f}) {
    scene.add_triangle(vec3(x, 0, 0), vec3(x + 1, 0, 0), vec3(x + 1, 1, 1));
    scene.add_triangle(vec3(x, 0, 0), vec3(x + 1, 1, 1), vec3(x, 1, 1));
  }
  const TriangleMesh mesh = scene.view();
  const KdTree tree = build_kdtree(mesh);
  ASSERT_FALSE(tree.nodes.empty());
  ASSERT_FALSE(tree.nodes[0].is_leaf());
  EXPECT_EQ(tree.nodes[0].axis(), 0);
  EXPECT_GE(tree.nodes[0].split, 1.0f);
  EXPECT_LE(tree.nodes[0].split, 10.0f);
  const KdTreeStats stats = compute_stats(tree);
  EXPECT_EQ(stats.references, 4u);  // nothing straddles
  EXPECT_NO_THROW(validate_kdtree(tree, mesh, kdtree_depth_limit(4, {})));
}

TEST(KdTreeBuild, RefitIsAClearError) {
  const TestMesh scene = testing::make_random_soup(11, 100);
  KdTree tree = build_kdtree(scene.view());
  try {
    refit(tree, scene.view());
    FAIL() << "refit of a kd-tree did not throw";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("not refittable"), std::string::npos) << error.what();
  }
}

TEST(KdTreeBuild, BadInputIsAClearError) {
  const TestMesh scene = testing::make_random_soup(12, 50);
  KdTreeOptions options;
  options.empty_bonus = 1.0f;
  EXPECT_THROW(build_kdtree(scene.view(), options), Error);
  options = {};
  options.intersection_cost = 0.0f;
  EXPECT_THROW(build_kdtree(scene.view(), options), Error);
  std::vector<vec3> positions{vec3(0), vec3(1, 0, 0), vec3(0, 1, 0)};
  positions[2].y = std::nanf("");
  const std::vector<uint32_t> indices{0, 1, 2};
  EXPECT_THROW(build_kdtree(make_indexed_mesh(positions, indices)), Error);

  const KdTree tree = build_kdtree(scene.view());
  const TestMesh other = testing::make_random_soup(13, 60);
  std::vector<Ray> rays(3);
  std::vector<Hit> hits(2);
  EXPECT_THROW(trace_closest(tree, scene.view(), rays, hits), Error);
  hits.resize(3);
  EXPECT_THROW(trace_closest(tree, other.view(), rays, hits), Error);
  EXPECT_NO_THROW(trace_closest(tree, scene.view(), rays, hits));
}

TEST(KdTreeBuild, EmptyMeshMissesEverything) {
  const TestMesh empty;
  const KdTree tree = build_kdtree(empty.view());
  EXPECT_TRUE(tree.nodes.empty());
  EXPECT_NO_THROW(validate_kdtree(tree, empty.view(), 8));
  const Ray ray;
  Hit hit;
  trace_closest(tree, empty.view(), std::span(&ray, 1), std::span(&hit, 1));
  EXPECT_FALSE(hit.valid());
}

}  // namespace
}  // namespace glint::accel
