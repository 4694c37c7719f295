#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_validate.h"
#include "core/error.h"
#include "accel/test_scenes.h"
#include "wide_bvh_test_support.h"

#include <gtest/gtest.h>

#include <string>
#include <tuple>

namespace glint::accel {
namespace {

using testing::TestMesh;

template <int N>
double mean_children(const WideBvh<N>& wide) {
  size_t used = 0;
  for (const WideNode<N>& node : wide.nodes)
    for (int lane = 0; lane < N; ++lane) used += node.is_empty(lane) ? 0 : 1;
  return static_cast<double>(used) / static_cast<double>(wide.nodes.size());
}

using StructureParam = std::tuple<BvhBuilder, uint32_t, bool>;

class WideBvhStructure : public ::testing::TestWithParam<StructureParam> {
protected:
  template <int N>
  void check(const TestMesh& scene) {
    const auto [builder, leaf_size, merge] = GetParam();
    BuildOptions options;
    options.max_leaf_size = leaf_size;
    WideCollapseOptions collapse;
    if (!merge) collapse.merge_leaf_size = 0;
    const TriangleMesh mesh = scene.view();
    const Bvh bvh = build_bvh(builder, mesh, options);
    const WideBvh<N> wide = collapse_to_wide<N>(bvh, mesh, collapse);
    EXPECT_NO_THROW(validate_wide_bvh(wide, mesh));
    EXPECT_EQ(wide.builder, bvh.builder);
    EXPECT_EQ(wide.bounds.min, bvh.bounds().min);
    EXPECT_EQ(wide.bounds.max, bvh.bounds().max);
    EXPECT_LE(wide.depth, bvh.depth);
    if (!merge) {
      // Without merging, collapse keeps the binary leaves one for one.
      EXPECT_EQ(wide.leaf_count, compute_stats(bvh).leaves);
    }
    if (builder != BvhBuilder::none) {
      // Collapsing removes levels: the tree is shallower than the binary one and its nodes hold
      // clearly more than two children on average.
      EXPECT_LT(wide.depth, bvh.depth);
      EXPECT_GT(mean_children(wide), N == 4 ? 2.5 : 3.5);
    }
  }
};

TEST_P(WideBvhStructure, RandomSoup4) { check<4>(testing::make_random_soup(61, 2000)); }
TEST_P(WideBvhStructure, RandomSoup8) { check<8>(testing::make_random_soup(61, 2000)); }
TEST_P(WideBvhStructure, Clustered4) { check<4>(testing::make_clustered(62, 3000)); }
TEST_P(WideBvhStructure, Clustered8) { check<8>(testing::make_clustered(62, 3000)); }

std::vector<StructureParam> structure_params() {
  std::vector<StructureParam> params;
  for (const BvhBuilder builder : testing::collapsible_builders())
    for (const unsigned leaf_size : {1u, 4u, 8u})
      if (builder != BvhBuilder::none || leaf_size == 1u)
        for (const bool merge : {true, false}) params.emplace_back(builder, leaf_size, merge);
  return params;
}

INSTANTIATE_TEST_SUITE_P(Accel, WideBvhStructure, ::testing::ValuesIn(structure_params()),
                         [](const ::testing::TestParamInfo<StructureParam>& param_info) {
                           return std::string(builder_name(std::get<0>(param_info.param))) + "_leaf" +
                                  std::to_string(std::get<1>(param_info.param)) +
                                  (std::get<2>(param_info.param) ? "_merged" : "_binaryleaves");
                         });

TEST(WideBvhCollapse, OpensTheLargestChildFirst) {
  // A hand-made binary tree, boxes flat in z so the half area is the x extent (y extent 1):
  //   0 root -> 1 (x 0..100, area 100), 2 (x 200..240, area 40)
  //   1 -> 3 (x 0..10), 4 (x 90..100);  2 -> leaves 5, 6;  3 -> leaves 7, 8;  4 -> leaves 9, 10
  // A 4-wide root starts with {1, 2}, opens 1 (largest) -> {3, 2, 4}, then 2 (40 > 10) ->
  // {3, 5, 4, 6}: two interior lanes and the two leaves of node 2. Opening smaller nodes first
  // would pull up leaves 7, 8 instead.
  TestMesh mesh;
  const auto triangle_at = [&](float x) { mesh.add_triangle(vec3(x, 0, 0), vec3(x + 1, 0, 0), vec3(x, 1, 0)); };
  for (float x : {0.0f, 9.0f, 90.0f, 99.0f, 200.0f, 239.0f}) triangle_at(x);  // prims 0..5
  const TriangleMesh view = mesh.view();
  const auto box = [](float x0, float x1) { return Aabb{vec3(x0, 0, 0), vec3(x1, 1, 0)}; };
  const auto interior = [&](float x0, float x1, uint32_t left) {
    BvhNode node;
    node.set_bounds(box(x0, x1));
    node.first = left;
    return node;
  };
  const auto leaf = [&](float x0, uint32_t prim) {
    BvhNode node;
    node.set_bounds(box(x0, x0 + 1));
    node.first = prim;
    node.prim_count = 1;
    return node;
  };
  Bvh bvh;
  bvh.nodes = {interior(0, 240, 1),  interior(0, 100, 3), interior(200, 240, 5), interior(0, 10, 7),
               interior(90, 100, 9), leaf(200, 4),        leaf(239, 5),          leaf(0, 0),
               leaf(9, 1),           leaf(90, 2),         leaf(99, 3)};
  bvh.prim_indices = {0, 1, 2, 3, 4, 5};
  bvh.depth = 4;
  bvh.builder = "hand-made";
  WideCollapseOptions collapse;
  collapse.merge_leaf_size = 0;
  const WideBvh4 wide = collapse_to_wide<4>(bvh, view, collapse);
  ASSERT_NO_THROW(validate_wide_bvh(wide, view));
  ASSERT_EQ(wide.nodes.size(), 3u);  // the root and nodes 3 and 4
  EXPECT_EQ(wide.depth, 2u);
  const WideNode<4>& root = wide.nodes[0];
  int root_leaves = 0;
  for (int lane = 0; lane < 4; ++lane) {
    ASSERT_FALSE(root.is_empty(lane));
    if (!root.is_leaf(lane)) {
      EXPECT_EQ(half_area(root.child_bounds(lane)), 10.0f);  // nodes 3 and 4 stay interior
      continue;
    }
    ++root_leaves;
    EXPECT_GE(root.child_bounds(lane).min.x, 200.0f) << "a leaf of node 3 or 4 was pulled up";
  }
  EXPECT_EQ(root_leaves, 2);
}

TEST(WideBvhCollapse, MergesSmallConsecutiveSubtreesIntoOneLeaf) {
  const TestMesh soup = testing::make_random_soup(63, 1000);
  const TriangleMesh view = soup.view();
  BuildOptions options;
  options.max_leaf_size = 1;
  const Bvh bvh = build_bvh(BvhBuilder::sah, view, options);
  const WideBvh8 merged = collapse_to_wide<8>(bvh, view);
  WideCollapseOptions keep;
  keep.merge_leaf_size = 0;
  const WideBvh8 kept = collapse_to_wide<8>(bvh, view, keep);
  ASSERT_NO_THROW(validate_wide_bvh(merged, view));
  EXPECT_EQ(kept.leaf_count, 1000u);        // one binary leaf per triangle
  EXPECT_LT(merged.leaf_count, 1000u / 2);  // most leaves now hold several triangles
  for (const WideNode<8>& node : merged.nodes)
    for (int lane = 0; lane < 8; ++lane) EXPECT_LE(node.prim_count[lane], 8u);
}

TEST(WideBvhCollapse, SingleTriangleAndEmptyMesh) {
  TestMesh one;
  one.add_triangle(vec3(0), vec3(1, 0, 0), vec3(0, 1, 0));
  const TriangleMesh view = one.view();
  const WideBvh8 wide = collapse_to_wide<8>(build_bvh(BvhBuilder::sah, view), view);
  EXPECT_NO_THROW(validate_wide_bvh(wide, view));
  EXPECT_EQ(wide.nodes.size(), 1u);
  EXPECT_EQ(wide.blocks.size(), 1u);
  EXPECT_EQ(wide.blocks[0].prim[0], 0u);
  EXPECT_EQ(wide.blocks[0].prim[1], Hit::kInvalidIndex);

  const TestMesh empty;
  const TriangleMesh empty_view = empty.view();
  const WideBvh4 none = collapse_to_wide<4>(build_bvh(BvhBuilder::sah, empty_view), empty_view);
  EXPECT_TRUE(none.nodes.empty());
  EXPECT_TRUE(none.blocks.empty());
  EXPECT_NO_THROW(validate_wide_bvh(none, empty_view));
}

TEST(WideBvhCollapse, BadInputsAreClearErrors) {
  const TestMesh soup = testing::make_random_soup(64, 100);
  const TestMesh other = testing::make_random_soup(65, 120);
  const Bvh bvh = build_bvh(BvhBuilder::sah, soup.view());
  EXPECT_THROW(collapse_to_wide<4>(bvh, other.view()), Error);
  Bvh misordered = bvh;
  misordered.nodes[0].first = 0;  // root's children "before" it
  EXPECT_THROW(collapse_to_wide<8>(misordered, soup.view()), Error);
  Bvh too_deep = bvh;
  too_deep.depth = kMaxBvhDepth + 1;
  EXPECT_THROW(collapse_to_wide<8>(too_deep, soup.view()), Error);
}

TEST(WideBvhValidate, CatchesBrokenStructures) {
  const TestMesh soup = testing::make_random_soup(66, 500);
  const TriangleMesh view = soup.view();
  const WideBvh4 wide = collapse_to_wide<4>(build_bvh(BvhBuilder::sah, view), view);
  ASSERT_NO_THROW(validate_wide_bvh(wide, view));

  WideBvh4 duplicate = wide;  // one triangle twice, another never
  duplicate.blocks[0].prim[0] = duplicate.blocks[1].prim[0];
  EXPECT_THROW(validate_wide_bvh(duplicate, view), Error);

  WideBvh4 moved = wide;  // a gathered corner no longer matches the mesh
  moved.blocks[2].v[1][0][0] += 1.0f;
  EXPECT_THROW(validate_wide_bvh(moved, view), Error);

  WideBvh4 shrunk = wide;  // a child box no longer contains its subtree
  shrunk.nodes[0].bounds[0][1][0] = shrunk.nodes[0].bounds[0][0][0];
  EXPECT_THROW(validate_wide_bvh(shrunk, view), Error);

  WideBvh4 wrong_depth = wide;
  wrong_depth.depth += 1;
  EXPECT_THROW(validate_wide_bvh(wrong_depth, view), Error);
}

TEST(WideBvhCollapse, SplitReferenceBvhIsAClearError) {
  const testing::TestMesh soup = testing::make_random_soup(63, 500);
  const TriangleMesh mesh = soup.view();
  const Bvh sbvh = build_bvh(BvhBuilder::sbvh, mesh);
  try {
    collapse_to_wide<8>(sbvh, mesh);
    FAIL() << "collapsing an sbvh must fail";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("split references"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace glint::accel
