// The pieces of the Morton-order builders: the Karras radix tree, leaf collapsing and the depth
// limit (bvh_collapse_leaves), treelet restructuring (trbvh) and PLOC's options. The whole builders
// are also covered by every test that iterates kAllBvhBuilders.
#include "accel/builders/binary_tree.h"
#include "accel/builders/build_lbvh.h"
#include "accel/builders/build_ploc.h"
#include "accel/builders/build_trbvh.h"
#include "accel/builders/bvh_collapse_leaves.h"
#include "accel/bvh_stats.h"
#include "accel/bvh_validate.h"
#include "accel/builders/primitive_bounds.h"
#include "core/error.h"
#include "same_tree_check.h"
#include "accel/test_scenes.h"
#include "thread_count_check.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cmath>
#include <cstring>
#include <string>
#include <limits>
#include <random>
#include <utility>
#include <vector>

namespace glint::accel {
namespace {

using detail::BinaryTree;
using detail::kNoNode;

// Walks the tree from the root checking parent links and boxes; returns the leaves left to right.
std::vector<uint32_t> checked_leaf_order(const BinaryTree& tree) {
  std::vector<uint32_t> leaves;
  if (tree.leaf_count == 0) return leaves;
  EXPECT_EQ(tree.nodes[tree.root].parent, kNoNode);
  std::vector<uint32_t> stack{tree.root};
  size_t visited = 0;
  while (!stack.empty() && visited <= tree.nodes.size()) {
    const uint32_t index = stack.back();
    stack.pop_back();
    ++visited;
    const detail::TreeNode& node = tree.nodes[index];
    if (node.is_leaf()) {
      EXPECT_LT(index, tree.leaf_count);
      leaves.push_back(index);
      continue;
    }
    EXPECT_GE(index, tree.leaf_count);
    for (const uint32_t child : {node.left, node.right}) {
      EXPECT_EQ(tree.nodes[child].parent, index);
      EXPECT_TRUE(node.box.contains(tree.nodes[child].box.min) && node.box.contains(tree.nodes[child].box.max));
    }
    stack.push_back(node.right);
    stack.push_back(node.left);
  }
  EXPECT_EQ(visited, tree.nodes.size()) << "every node reachable exactly once";
  return leaves;
}

std::vector<uint32_t> sorted_prims(const BinaryTree& tree) {
  std::vector<uint32_t> prims;
  for (const uint32_t leaf : checked_leaf_order(tree)) prims.push_back(tree.nodes[leaf].prim);
  std::sort(prims.begin(), prims.end());
  return prims;
}

// Length of the common prefix of sorted keys a and b: the code, then the 32-bit position.
int key_prefix(const MortonOrder& order, uint32_t a, uint32_t b) {
  const uint64_t x = order.codes[a], y = order.codes[b];
  return x != y ? std::countl_zero(x ^ y) : 64 + std::countl_zero(a ^ b);
}

// Checks the tree against the definition of Karras's radix tree, by brute force: every interior node
// over keys [first, last] splits where the common prefix of neighbouring keys is shortest in that
// range (one such place exists: the keys share a prefix and differ in the next bit), and is stored
// at leaf_count + split. Returns the node's key range.
std::pair<uint32_t, uint32_t> check_radix_node(const BinaryTree& tree, const MortonOrder& order, uint32_t node) {
  const detail::TreeNode& n = tree.nodes[node];
  if (n.is_leaf()) return {node, node};
  const auto [first, left_last] = check_radix_node(tree, order, n.left);
  const auto [right_first, last] = check_radix_node(tree, order, n.right);
  EXPECT_EQ(right_first, left_last + 1);
  uint32_t shortest = first;
  for (uint32_t b = first + 1; b < last; ++b)
    if (key_prefix(order, b, b + 1) < key_prefix(order, shortest, shortest + 1)) shortest = b;
  EXPECT_EQ(left_last, shortest) << "split of the node over keys [" << first << ", " << last << "]";
  EXPECT_EQ(node, tree.leaf_count + left_last);
  return {first, last};
}

std::vector<uint32_t> iota_vector(uint32_t count) {
  std::vector<uint32_t> values(count);
  for (uint32_t i = 0; i < count; ++i) values[i] = i;
  return values;
}

PrimitiveBounds unit_boxes_along_x(uint32_t count) {
  PrimitiveBounds bounds;
  for (uint32_t i = 0; i < count; ++i) {
    const auto x = static_cast<float>(i);
    bounds.boxes.push_back(Aabb{vec3(x, 0.0f, 0.0f), vec3(x + 1.0f, 1.0f, 1.0f)});
    bounds.centroids.push_back(bounds.boxes.back().center());
  }
  return bounds;
}

TEST(KarrasTree, InOrderLeavesFollowTheSortedCodesEvenWithDuplicates) {
  std::mt19937_64 rng(3);
  for (const uint32_t count : {2u, 3u, 17u, 1000u, 20000u}) {
    for (const uint64_t distinct : {uint64_t{1}, uint64_t{5}, uint64_t{1} << 40}) {
      MortonOrder order;
      order.bits = 63;
      order.codes = detail::ParallelArray<uint64_t>(count);
      for (uint32_t i = 0; i < count; ++i) order.codes[i] = rng() % distinct;
      std::sort(order.codes.begin(), order.codes.end());
      const std::vector<uint32_t> identity = iota_vector(count);
      order.prims.assign(identity.begin(), identity.end());
      const PrimitiveBounds bounds = unit_boxes_along_x(count);
      const BinaryTree tree = detail::build_karras_tree(bounds.input(), order);
      ASSERT_EQ(tree.nodes.size(), 2 * size_t{count} - 1);
      // A radix tree over sorted keys lists its leaves in key order.
      EXPECT_EQ(checked_leaf_order(tree), iota_vector(count)) << count << " leaves, " << distinct << " codes";
      const auto [first, last] = check_radix_node(tree, order, tree.root);
      EXPECT_EQ(first, 0u);
      EXPECT_EQ(last, count - 1);
      if (distinct == 1) {  // all codes equal: the index tie-break gives a balanced tree
        const auto summaries = detail::summarise_tree(tree, BuildOptions{});
        BuildOptions single;
        single.max_leaf_size = 1;
        const auto no_collapse = detail::summarise_tree(tree, single);
        EXPECT_EQ(no_collapse[tree.root].height, 1u + static_cast<uint32_t>(std::bit_width(count - 1)));
      }
    }
  }
}

TEST(LeafCollapse, BvhSahEqualsTheTreeCostAndNeverExceedsNoCollapsing) {
  const testing::TestMesh scene = testing::make_clustered(41, 20000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  for (const uint32_t leaf_size : {1u, 2u, 4u, 8u}) {
    BuildOptions options;
    options.max_leaf_size = leaf_size;
    BinaryTree tree = detail::build_lbvh_tree(bounds.input());
    const double tree_cost = detail::summarise_tree(tree, options)[tree.root].cost;
    const Bvh bvh = detail::flatten_tree(tree, options, "lbvh");
    EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, leaf_size));
    const BvhStats stats = compute_stats(bvh);
    EXPECT_NEAR(stats.sah_cost, tree_cost / half_area(bvh.bounds()), 1e-9 * stats.sah_cost);
    BuildOptions single = options;
    single.max_leaf_size = 1;
    EXPECT_LE(stats.sah_cost, compute_stats(build_lbvh(bounds.input(), single)).sah_cost * (1.0 + 1e-12));
    EXPECT_LE(stats.max_leaf_size, leaf_size);
  }
  // A traversal far dearer than intersecting: every subtree that fits in a leaf becomes one.
  BuildOptions dear;
  dear.traversal_cost = 1e6f;
  const Bvh collapsed = build_lbvh(bounds.input(), dear);
  const BvhStats stats = compute_stats(collapsed);
  EXPECT_GT(stats.mean_leaf_size, 2.0);
}

TEST(DepthLimit, ACaterpillarTreeIsRebalancedWithinTheTraversalLimit) {
  // 300 leaves hanging off one spine: depth 300 as built, far beyond kMaxBvhDepth.
  const uint32_t count = 300;
  const PrimitiveBounds bounds = unit_boxes_along_x(count);
  BinaryTree tree = detail::make_leaves(bounds.input(), iota_vector(count));
  uint32_t below = 0;  // the spine's current bottom
  for (uint32_t i = 1; i < count; ++i) {
    const uint32_t node = count + i - 1;
    tree.nodes[node].left = below;
    tree.nodes[node].right = i;
    tree.nodes[below].parent = node;
    tree.nodes[i].parent = node;
    below = node;
  }
  tree.root = below;
  detail::fit_interior_boxes(tree);
  BuildOptions options;
  options.max_leaf_size = 1;
  ASSERT_GT(detail::summarise_tree(tree, options)[tree.root].height, kMaxBvhDepth);
  const Bvh bvh = detail::flatten_tree(tree, options, "test");
  EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, 1));
  EXPECT_LE(bvh.depth, kMaxBvhDepth);
  EXPECT_EQ(sorted_prims(tree), iota_vector(count));
}

TEST(DepthLimit, BottomUpBuildersStayWithinTheLimitOnAdversarialInput) {
  // Geometrically shrinking boxes: PLOC merges them one at a time into a chain.
  PrimitiveBounds bounds;
  float size = 1.0f;
  for (int i = 0; i < 2000; ++i) {
    bounds.boxes.push_back(Aabb{vec3(size), vec3(2.0f * size)});
    bounds.centroids.push_back(vec3(1.5f * size));
    size *= 0.97f;
  }
  BuildOptions options;
  options.max_leaf_size = 1;
  for (const Bvh& bvh : {build_lbvh(bounds.input(), options), build_trbvh(bounds.input(), options),
                         build_ploc(bounds.input(), options)}) {
    EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, 1)) << bvh.builder;
    EXPECT_LE(bvh.depth, kMaxBvhDepth) << bvh.builder;
  }
}

TEST(TreeletRestructuring, NeverIncreasesTheCostAndKeepsEveryPrimitive) {
  const testing::TestMesh scenes[] = {testing::make_clustered(42, 20000), testing::make_degenerate_soup(43, 8000),
                                      testing::make_random_soup(44, 8000)};
  for (const testing::TestMesh& scene : scenes) {
    const PrimitiveBounds bounds = triangle_bounds(scene.view());
    for (const uint32_t leaf_size : {1u, 4u}) {
      BuildOptions options;
      options.max_leaf_size = leaf_size;
      BinaryTree tree = detail::build_lbvh_tree(bounds.input());
      double cost = detail::summarise_tree(tree, options)[tree.root].cost;
      const Aabb root_box = tree.nodes[tree.root].box;
      uint32_t total_changes = 0;
      for (int round = 0; round < 3; ++round) {
        total_changes += detail::restructure_treelets(tree, options, 3);
        const double next = detail::summarise_tree(tree, options)[tree.root].cost;
        EXPECT_LE(next, cost) << "round " << round << ", " << scene.triangle_count() << " triangles";
        cost = next;
        EXPECT_EQ(sorted_prims(tree), iota_vector(scene.triangle_count()));
        EXPECT_EQ(tree.nodes[tree.root].box.min, root_box.min);
        EXPECT_EQ(tree.nodes[tree.root].box.max, root_box.max);
      }
      EXPECT_GT(total_changes, 0u) << "restructuring found nothing to improve on an LBVH";
    }
  }
}

TEST(TreeletRestructuring, ZeroRoundsIsTheLbvh) {
  const testing::TestMesh scene = testing::make_clustered(45, 5000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  BuildOptions options;
  options.treelet_rounds = 0;
  const Bvh trbvh = build_trbvh(bounds.input(), options);
  const Bvh lbvh = build_lbvh(bounds.input(), options);
  EXPECT_EQ(trbvh.builder, "trbvh");
  // The same tree; the layouts differ (lbvh lays its nodes out in the same pass, lbvh_layout.h).
  testing::expect_same_tree(lbvh, trbvh, "trbvh of 0 rounds");
  options.treelet_rounds = 3;
  EXPECT_LT(compute_stats(build_trbvh(bounds.input(), options)).sah_cost, compute_stats(lbvh).sah_cost);
}

TEST(Ploc, RadiusIsAnOptionAndZeroIsAnError) {
  const testing::TestMesh scene = testing::make_clustered(46, 6000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  BuildOptions options;
  options.ploc_radius = 0;
  EXPECT_THROW(build_ploc(bounds.input(), options), Error);
  for (const uint32_t radius : {1u, 4u, 16u, 64u}) {
    options.ploc_radius = radius;
    const Bvh bvh = build_ploc(bounds.input(), options);
    EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, options.max_leaf_size)) << "radius " << radius;
  }
  // Two primitives: one merge. Identical boxes everywhere: ties must still make progress.
  const std::vector<Aabb> boxes(5000, Aabb{vec3(0.0f), vec3(1.0f)});
  const std::vector<vec3> centroids(5000, vec3(0.5f));
  options.ploc_radius = 16;
  for (const size_t count : {size_t{2}, size_t{5000}}) {
    const BuildInput input{std::span(boxes).first(count), std::span(centroids).first(count)};
    EXPECT_NO_THROW(validate_bvh(build_ploc(input, options), input.boxes, options.max_leaf_size));
  }
}

TEST(BottomUpBuilders, OutputDoesNotDependOnTheThreadCount) {
  // Node ids come from sorted positions and prefix sums, never from which thread got there first:
  // one thread and all threads must give identical arrays.
  const testing::TestMesh scene = testing::make_degenerate_soup(48, 30000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  BuildOptions options;
  options.parallel_threshold = 64;
  for (const testing::Builder build : {&build_lbvh, &build_trbvh, &build_ploc})
    testing::expect_same_output_on_one_thread(build, bounds.input(), options);
}

TEST(Ploc, AWindowOverEverythingIsExactGreedyClustering) {
  // With the radius covering all clusters, the nearest neighbours are global, and merging all mutual
  // pairs per iteration builds the same tree as merging the globally closest pair one at a time
  // (Walter et al. 2008's agglomerative clustering), done here by brute force. Compared by SAH cost.
  const testing::TestMesh scene = testing::make_random_soup(47, 300);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  std::vector<Aabb> clusters = bounds.boxes;
  double interior_area = 0.0, leaf_area = 0.0;
  for (const Aabb& box : clusters) leaf_area += half_area(box);
  while (clusters.size() > 1) {
    float best = std::numeric_limits<float>::infinity();
    size_t best_i = 0, best_j = 1;
    for (size_t i = 0; i < clusters.size(); ++i)
      for (size_t j = i + 1; j < clusters.size(); ++j) {
        Aabb merged = clusters[i];
        merged.extend(clusters[j]);
        if (half_area(merged) < best) {
          best = half_area(merged);
          best_i = i;
          best_j = j;
        }
      }
    clusters[best_i].extend(clusters[best_j]);
    interior_area += half_area(clusters[best_i]);
    clusters.erase(clusters.begin() + static_cast<std::ptrdiff_t>(best_j));
  }
  BuildOptions options;
  options.max_leaf_size = 1;
  options.ploc_radius = 300;
  const double greedy = (options.traversal_cost * interior_area + leaf_area) / half_area(clusters[0]);
  EXPECT_NEAR(compute_stats(build_ploc(bounds.input(), options)).sah_cost, greedy, 1e-6 * greedy);
}

}  // namespace
}  // namespace glint::accel
