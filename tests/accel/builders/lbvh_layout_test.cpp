// lbvh's one-pass sweep and layout (lbvh_layout.h) against the BinaryTree path (build_karras_tree
// then flatten_tree), which builds the same radix tree and collapse node by node: the same tree must
// come out, whatever the chunk size, laid out with children after parents.
#include "accel/builders/build_lbvh.h"
#include "accel/builders/bvh_collapse_leaves.h"
#include "accel/bvh_validate.h"
#include "accel/builders/lbvh_layout.h"
#include "accel/builders/primitive_bounds.h"
#include "core/error.h"
#include "same_tree_check.h"
#include "accel/test_scenes.h"
#include "thread_count_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace glint::accel {
namespace {

Bvh binary_tree_lbvh(const BuildInput& input, const BuildOptions& options) {
  detail::ParallelArray<detail::SubtreeSummary> summaries;
  detail::BinaryTree tree = detail::build_karras_tree(input, sort_by_morton(input.centroids), options, summaries);
  return detail::flatten_tree(tree, std::move(summaries), options, "lbvh");
}

Bvh swept_lbvh(const BuildInput& input, const BuildOptions& options, uint32_t chunk_keys) {
  MortonOrder order = sort_by_morton(input.centroids);
  const detail::LbvhSweep sweep = detail::sweep_lbvh(input, order, options, chunk_keys);
  return detail::lay_out_lbvh(sweep, std::move(order.prims), "lbvh");
}

TEST(LbvhLayout, GivesTheBinaryTreePathsTreeWhateverTheChunkSize) {
  const testing::TestMesh scenes[] = {testing::make_clustered(46, 20000), testing::make_degenerate_soup(47, 8000),
                                      testing::make_random_soup(48, 3), testing::make_random_soup(49, 1)};
  for (const testing::TestMesh& scene : scenes) {
    const PrimitiveBounds bounds = triangle_bounds(scene.view());
    for (const uint32_t leaf_size : {1u, 4u, 8u}) {
      BuildOptions options;
      options.max_leaf_size = leaf_size;
      const Bvh binary = binary_tree_lbvh(bounds.input(), options);
      // 1: every key a chunk of its own, so the border pass builds the whole tree; 3: collapses
      // across chunk borders drop pairs the chunks wrote; one chunk: no border pass at all.
      for (const uint32_t chunk_keys : {1u, 3u, 64u, 1024u, 8192u, 1u << 20}) {
        const std::string where = std::to_string(scene.triangle_count()) + " triangles, leaf size " +
                                  std::to_string(leaf_size) + ", chunks of " + std::to_string(chunk_keys);
        const Bvh swept = swept_lbvh(bounds.input(), options, chunk_keys);
        testing::expect_same_tree(binary, swept, where);
        EXPECT_NO_THROW(validate_bvh(swept, bounds.boxes, leaf_size)) << where;  // children after parents
      }
    }
  }
}

TEST(LbvhLayout, CollapsesOverPairsThatChunksWrote) {
  // Leaves of up to 8 over chunks of 3 keys: a leaf across a chunk border takes in subtrees whose
  // pairs a chunk wrote (interior there: two far-apart triangles are cheaper apart), and the layout
  // must leave those pairs out.
  const testing::TestMesh scene = testing::make_clustered(50, 5000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  BuildOptions options;
  options.max_leaf_size = 8;
  MortonOrder order = sort_by_morton(bounds.centroids);
  const detail::LbvhSweep sweep = detail::sweep_lbvh(bounds.input(), order, options, 3);
  size_t written = 1 + 2 * size_t{sweep.top_pair_count};
  for (const detail::LbvhChunk& chunk : sweep.chunks) written += 2 * size_t{chunk.pair_count};
  const Bvh bvh = detail::lay_out_lbvh(sweep, std::move(order.prims), "lbvh");
  EXPECT_LT(bvh.nodes.size(), written);
  EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, 8));
  testing::expect_same_tree(binary_tree_lbvh(bounds.input(), options), bvh, "chunks of 3");
}

TEST(LbvhLayout, DoesNotDependOnTheThreadCount) {
  const testing::TestMesh scene = testing::make_clustered(51, 60000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  testing::expect_same_output_on_one_thread(build_lbvh, bounds.input(), BuildOptions{});
}

TEST(LbvhLayout, EmptyAndSingleKeyInputs) {
  const PrimitiveBounds none;
  const Bvh empty = build_lbvh(none.input());
  EXPECT_TRUE(empty.nodes.empty());
  EXPECT_TRUE(empty.prim_indices.empty());
  PrimitiveBounds one;
  one.boxes.push_back(Aabb{vec3(0.0f), vec3(1.0f)});
  one.centroids.push_back(vec3(0.5f));
  const Bvh single = build_lbvh(one.input());
  ASSERT_EQ(single.nodes.size(), 1u);
  EXPECT_EQ(single.nodes[0].prim_count, 1u);
  EXPECT_EQ(single.nodes[0].first, 0u);
  EXPECT_EQ(single.depth, 1u);
}

TEST(LbvhLayout, ChunkSizeFollowsTheKeyCountOnly) {
  EXPECT_EQ(detail::lbvh_chunk_keys(0), 1024u);
  EXPECT_EQ(detail::lbvh_chunk_keys(50000), 1024u);    // 50000 / 64 = 781, rounded up, then the floor
  EXPECT_EQ(detail::lbvh_chunk_keys(79412), 2048u);    // the deforming dinosaurs: 39 chunks
  EXPECT_EQ(detail::lbvh_chunk_keys(100000), 2048u);   // 100000 / 64 = 1562, rounded up
  EXPECT_EQ(detail::lbvh_chunk_keys(617800), 8192u);   // atrium: 76 chunks
  EXPECT_EQ(detail::lbvh_chunk_keys(1u << 30), 8192u);
  // build_lbvh's sweep is the one with that size.
  const testing::TestMesh scene = testing::make_clustered(53, 150000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  const Bvh swept = swept_lbvh(bounds.input(), BuildOptions{}, detail::lbvh_chunk_keys(150000));
  const Bvh built = build_lbvh(bounds.input());
  ASSERT_EQ(swept.nodes.size(), built.nodes.size());
  EXPECT_EQ(0, std::memcmp(swept.nodes.data(), built.nodes.data(), built.nodes.size() * sizeof(BvhNode)));
}

TEST(LbvhLayout, RejectsChunksOfNoKeys) {
  const testing::TestMesh scene = testing::make_random_soup(52, 10);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  EXPECT_THROW(detail::sweep_lbvh(bounds.input(), sort_by_morton(bounds.centroids), BuildOptions{}, 0), Error);
}

TEST(DepthLimit, AMortonChainDeeperThanTheLimitIsRebalanced) {
  // Centroids whose 63-bit codes are 0 (eight times), 1, 2, 4, ..., 2^62 and all ones: code bit
  // 3j + axis is cell 2^j on that axis of the unit cube, which the corner (1, 1, 1) spans. Their
  // radix tree is a chain of 63 levels over the balanced subtree of the eight zeros: 67 levels.
  PrimitiveBounds bounds;
  const auto add = [&](const vec3& centroid) {
    bounds.centroids.push_back(centroid);
    bounds.boxes.push_back(Aabb{centroid, centroid});
  };
  for (int copy = 0; copy < 8; ++copy) add(vec3(0.0f));
  for (int bit = 0; bit < 63; ++bit) {
    vec3 centroid(0.0f);
    centroid[bit % 3] = std::ldexp(1.0f, bit / 3 - 21);
    add(centroid);
  }
  add(vec3(1.0f));
  BuildOptions options;
  options.max_leaf_size = 1;
  const MortonOrder order = sort_by_morton(bounds.centroids);
  ASSERT_EQ(order.bits, 63u);
  const detail::LbvhSweep sweep = detail::sweep_lbvh(bounds.input(), order, options);
  ASSERT_GT(sweep.height, kMaxBvhDepth);
  EXPECT_THROW(detail::lay_out_lbvh(sweep, UnzeroedVector<uint32_t>(order.prims), "lbvh"), Error);
  const Bvh bvh = build_lbvh(bounds.input(), options);
  EXPECT_NO_THROW(validate_bvh(bvh, bounds.boxes, 1));
  EXPECT_LE(bvh.depth, kMaxBvhDepth);
}

}  // namespace
}  // namespace glint::accel
