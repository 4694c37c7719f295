// The parallel paths of the top-down builders and of refit against their serial counterparts and
// brute-force references: binning, partitioning, whole builds with the parallel path forced on and
// off, and refits of trees large enough to fork tasks.
#include "accel/builders/build_median.h"
#include "accel/builders/build_sah.h"
#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/bvh_validate.h"
#include "accel/builders/prim_partition.h"
#include "accel/builders/prim_ref.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/refit.h"
#include "accel/builders/sah_binning.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_refit.h"
#include "core/error.h"
#include "prim_ref_test_support.h"
#include "accel/test_scenes.h"
#include "thread_count_check.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace glint::accel {
namespace {

using detail::PrimRange;
using detail::PrimRef;
using testing::make_refs;

// Bins computed straight from the input, one primitive at a time: box and count per (axis, bin).
struct ExpectedBins {
  std::vector<Aabb> boxes;
  std::vector<uint32_t> counts;
};

ExpectedBins brute_force_bins(const PrimitiveBounds& bounds, std::span<const PrimRef> refs, const PrimRange& range,
                              const detail::BinMapping& mapping) {
  ExpectedBins bins{std::vector<Aabb>(3 * mapping.bin_count), std::vector<uint32_t>(3 * mapping.bin_count, 0)};
  for (uint32_t i = range.begin; i != range.end; ++i) {
    const uint32_t prim = refs[i].prim;
    for (int axis = 0; axis < 3; ++axis) {
      const uint32_t slot = static_cast<uint32_t>(axis) * mapping.bin_count + mapping.bin(bounds.centroids[prim], axis);
      bins.boxes[slot].extend(bounds.boxes[prim]);
      ++bins.counts[slot];
    }
  }
  return bins;
}

bool same_bins(const detail::SahBins& bins, const ExpectedBins& expected) {
  for (int axis = 0; axis < 3; ++axis)
    for (uint32_t b = 0; b < bins.bin_count; ++b) {
      const uint32_t slot = static_cast<uint32_t>(axis) * bins.bin_count + b;
      if (bins.count(axis, b) != expected.counts[slot] || bins.box(axis, b).min != expected.boxes[slot].min ||
          bins.box(axis, b).max != expected.boxes[slot].max)
        return false;
    }
  return true;
}

TEST(SahBinning, ParallelBinningEqualsSerialBinningExactly) {
  const testing::TestMesh scene = testing::make_clustered(5, 200000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  PrimRange root;
  const std::vector<PrimRef> refs = make_refs(bounds, root);
  const PrimRange part = detail::bound_refs(refs, 1000, 150000, false, 1024);
  for (const uint32_t bin_count : {2u, 16u, 32u, 256u}) {
    for (const PrimRange& range : {root, part}) {
      const std::optional<detail::BinMapping> mapping = detail::bin_mapping(range.centroid_box, bin_count);
      ASSERT_TRUE(mapping);
      detail::SahBins serial;
      detail::bin_refs(refs, range, *mapping, false, 1024, serial);
      EXPECT_TRUE(same_bins(serial, brute_force_bins(bounds, refs, range, *mapping))) << bin_count << " bins";
      uint32_t total = 0;
      for (uint32_t b = 0; b < bin_count; ++b) total += serial.count(1, b);
      EXPECT_EQ(total, range.size());
      for (const uint32_t chunk : {64u, 1000u, 16384u}) {
        detail::SahBins parallel;
        detail::bin_refs(refs, range, *mapping, true, chunk, parallel);
        EXPECT_TRUE(parallel == serial) << bin_count << " bins, chunks of " << chunk;
      }
    }
  }
}

TEST(SahBinning, SweepFindsTheCheapestBoundaryOfABruteForceSearch) {
  // The sweep skips empty bins, and small ranges are searched without bins; a search over every
  // boundary, each side's box merged from scratch in the same order, must pick the same axis and
  // boundary at the same cost, ties to the first.
  const testing::TestMesh scene = testing::make_clustered(6, 20000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  PrimRange root;
  const std::vector<PrimRef> refs = make_refs(bounds, root);
  std::mt19937 rng(7);  // 32-bit results
  const auto next = [&rng] { return static_cast<uint32_t>(rng()); };
  int checked = 0, checked_small = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const uint32_t size = 2 + next() % (trial % 2 == 0 ? detail::kSmallSahRange - 1 : 400u);
    const uint32_t begin = next() % (root.size() - size);
    const PrimRange range = detail::bound_refs(refs, begin, begin + size, false, 1024);
    const uint32_t bin_count = trial % 3 == 0 ? 16u : 2u + next() % 60u;
    const std::optional<detail::BinMapping> mapping = detail::bin_mapping(range.centroid_box, bin_count);
    if (!mapping) continue;
    detail::SahBins bins;
    detail::bin_refs(refs, range, *mapping, false, 1024, bins);
    std::optional<detail::SahSplit> expected;
    float expected_cost = std::numeric_limits<float>::infinity();
    for (int axis = 0; axis < 3; ++axis) {
      if (mapping->scale[axis] == 0.0f) continue;
      for (uint32_t boundary = 1; boundary < bin_count; ++boundary) {
        Aabb left, right;
        uint32_t left_count = 0, right_count = 0;
        for (uint32_t b = 0; b < boundary; ++b) {
          left.extend(bins.box(axis, b));
          left_count += bins.count(axis, b);
        }
        for (uint32_t b = bin_count - 1; b >= boundary; --b) {
          right.extend(bins.box(axis, b));
          right_count += bins.count(axis, b);
        }
        if (left_count == 0 || right_count == 0) continue;
        const float cost = half_area(left) * static_cast<float>(left_count) +
                           half_area(right) * static_cast<float>(right_count);
        if (cost < expected_cost) {
          expected_cost = cost;
          expected = detail::SahSplit{axis, boundary, cost};
        }
      }
    }
    const std::optional<detail::SahSplit> best = detail::best_sah_split(bins, *mapping, range.size());
    ASSERT_EQ(best.has_value(), expected.has_value()) << "trial " << trial;
    if (size <= detail::kSmallSahRange) {
      // Small ranges skip the bins altogether and must still agree.
      const std::optional<detail::SahSplit> small = detail::best_sah_split_small(refs, range, *mapping);
      ASSERT_EQ(small.has_value(), expected.has_value()) << "trial " << trial;
      if (small) {
        EXPECT_EQ(small->axis, expected->axis) << "trial " << trial;
        EXPECT_EQ(small->boundary, expected->boundary) << "trial " << trial;
        EXPECT_EQ(small->cost, expected->cost) << "trial " << trial;
        ++checked_small;
      }
    }
    if (!best) continue;
    EXPECT_EQ(best->axis, expected->axis) << "trial " << trial;
    EXPECT_EQ(best->boundary, expected->boundary) << "trial " << trial;
    EXPECT_EQ(best->cost, expected->cost) << "trial " << trial;
    ++checked;
  }
  EXPECT_GT(checked, 2500);
  EXPECT_GT(checked_small, 1200);
}

// Checks one side of a split against the input: the references satisfy (or not) the predicate, the
// bounds are those of exactly these references.
template <typename GoesLeft>
void expect_side(std::span<const PrimRef> refs, const PrimRange& side, bool left, GoesLeft goes_left) {
  PrimRange expected{side.begin, side.end, {}, {}};
  for (uint32_t i = side.begin; i != side.end; ++i) {
    EXPECT_EQ(goes_left(refs[i]), left) << "slot " << i;
    expected.extend(refs[i]);
  }
  EXPECT_EQ(side.box.min, expected.box.min);
  EXPECT_EQ(side.box.max, expected.box.max);
  EXPECT_EQ(side.centroid_box.min, expected.centroid_box.min);
  EXPECT_EQ(side.centroid_box.max, expected.centroid_box.max);
}

std::vector<uint32_t> sorted_prims(std::span<const PrimRef> refs, uint32_t begin, uint32_t end) {
  std::vector<uint32_t> prims;
  for (uint32_t i = begin; i != end; ++i) prims.push_back(refs[i].prim);
  std::sort(prims.begin(), prims.end());
  return prims;
}

TEST(TopDownPartition, ParallelAndInPlaceGiveTheSameSidesWithTheirBounds) {
  const testing::TestMesh scene = testing::make_random_soup(8, 50000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  PrimRange root;
  const std::vector<PrimRef> input = make_refs(bounds, root);
  const PrimRange range = detail::bound_refs(input, 100, 49000, false, 1024);
  const float middle = range.centroid_box.center().x;
  const auto below = [middle](const PrimRef& ref) { return ref.centroid.x < middle; };
  const auto all = [](const PrimRef&) { return true; };
  const auto none = [](const PrimRef&) { return false; };
  const auto check = [&](auto goes_left, uint32_t expected_left) {
    std::vector<PrimRef> in_place = input;
    const detail::Split a = detail::partition_in_place(in_place, range, goes_left);
    EXPECT_FALSE(a.moved);
    for (const uint32_t chunk : {97u, 4096u}) {
      std::vector<PrimRef> moved(input.size());
      const detail::Split b = detail::partition_parallel(input, moved, range, chunk, goes_left);
      EXPECT_TRUE(b.moved);
      ASSERT_EQ(a.left.end, range.begin + expected_left);
      ASSERT_EQ(b.left.end, a.left.end);
      EXPECT_EQ(b.right.begin, a.right.begin);
      EXPECT_EQ(b.right.end, range.end);
      expect_side(moved, b.left, true, goes_left);
      expect_side(moved, b.right, false, goes_left);
      EXPECT_EQ(sorted_prims(moved, range.begin, range.end), sorted_prims(input, range.begin, range.end));
      // Stable: each side keeps the input order.
      std::vector<uint32_t> left_in_order, right_in_order;
      for (uint32_t i = range.begin; i != range.end; ++i)
        (goes_left(input[i]) ? left_in_order : right_in_order).push_back(input[i].prim);
      for (uint32_t i = range.begin; i != range.end; ++i)
        EXPECT_EQ(moved[i].prim, i < b.left.end ? left_in_order[i - range.begin]
                                                : right_in_order[i - b.right.begin]);
    }
    expect_side(in_place, a.left, true, goes_left);
    expect_side(in_place, a.right, false, goes_left);
    EXPECT_EQ(sorted_prims(in_place, range.begin, range.end), sorted_prims(input, range.begin, range.end));
    // Outside the range nothing moved.
    for (uint32_t i = 0; i < input.size(); ++i) {
      if (i < range.begin || i >= range.end) {
        ASSERT_EQ(in_place[i].prim, input[i].prim);
      }
    }
  };
  uint32_t left = 0;
  for (uint32_t i = range.begin; i != range.end; ++i) left += below(input[i]) ? 1u : 0u;
  ASSERT_GT(left, 1000u);
  ASSERT_LT(left, range.size() - 1000u);
  check(below, left);
  check(all, range.size());
  check(none, 0);
}

// Leaves of two BVHs with identical nodes hold the same primitives (in any order).
void expect_same_leaf_sets(const Bvh& a, const Bvh& b) {
  for (const BvhNode& node : a.nodes) {
    if (!node.is_leaf()) continue;
    std::vector<uint32_t> x(a.prim_indices.begin() + node.first, a.prim_indices.begin() + node.first + node.prim_count);
    std::vector<uint32_t> y(b.prim_indices.begin() + node.first, b.prim_indices.begin() + node.first + node.prim_count);
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    ASSERT_EQ(x, y) << "leaf at slot " << node.first;
  }
}

TEST(TopDownParallelBuild, ForcedParallelPathGivesTheSameTreeAsTheSerialPath) {
  // Parallel binning, partitioning, bounding and renumbering everywhere (threshold 1) or nowhere:
  // the same nodes, hence the same SAH; only the order inside a leaf may differ.
  const testing::TestMesh scene = testing::make_clustered(10, 60000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  for (const auto build : {&build_sah, &build_median}) {
    BuildOptions serial_options, forced_options;
    serial_options.parallel_threshold = std::numeric_limits<uint32_t>::max();
    forced_options.parallel_threshold = 1;
    const Bvh serial = build(bounds.input(), serial_options);
    const Bvh forced = build(bounds.input(), forced_options);
    const Bvh usual = build(bounds.input(), BuildOptions{});
    for (const Bvh* bvh : {&serial, &forced, &usual}) {
      EXPECT_NO_THROW(validate_bvh(*bvh, bounds.boxes, BuildOptions{}.max_leaf_size)) << bvh->builder;
      ASSERT_EQ(bvh->nodes.size(), serial.nodes.size()) << bvh->builder;
      EXPECT_EQ(0, std::memcmp(bvh->nodes.data(), serial.nodes.data(), serial.nodes.size() * sizeof(BvhNode)))
          << bvh->builder;
      EXPECT_EQ(bvh->depth, serial.depth);
      EXPECT_EQ(compute_stats(*bvh).sah_cost, compute_stats(serial).sah_cost);
      expect_same_leaf_sets(*bvh, serial);
    }
  }
}

TEST(TopDownParallelBuild, OutputDoesNotDependOnTheThreadCount) {
  const testing::TestMesh scene = testing::make_degenerate_soup(11, 40000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  BuildOptions options;
  options.parallel_threshold = 64;
  for (const testing::Builder build : {&build_sah, &build_median})
    testing::expect_same_output_on_one_thread(build, bounds.input(), options);
}

void deform(testing::TestMesh& mesh, float amount) {
  for (vec3& p : mesh.positions)
    p += amount * vec3(std::sin(3.0f * p.y), std::cos(2.0f * p.z), std::sin(p.x + p.y));
}

TEST(ParallelRefit, BinaryBoxesEqualASerialBottomUpRecomputation) {
  // 60k triangles: enough nodes for refit to fork tasks over several levels.
  testing::TestMesh mesh = testing::make_clustered(12, 60000);
  for (const BvhBuilder builder : {BvhBuilder::sah, BvhBuilder::lbvh}) {
    testing::TestMesh moved = mesh;
    Bvh from_mesh = build_bvh(builder, mesh.view());
    deform(moved, 0.05f);
    Bvh from_boxes = from_mesh;
    refit(from_mesh, moved.view());
    const PrimitiveBounds bounds = triangle_bounds(moved.view());
    refit(from_boxes, bounds.boxes);
    // Reference: leaves from their triangles, then a reverse sweep (children after parents).
    std::vector<Aabb> expected(from_mesh.nodes.size());
    for (size_t i = from_mesh.nodes.size(); i-- > 0;) {
      const BvhNode& node = from_mesh.nodes[i];
      if (node.is_leaf()) {
        for (uint32_t slot = node.first; slot != node.first + node.prim_count; ++slot)
          expected[i].extend(bounds.boxes[from_mesh.prim_indices[slot]]);
      } else {
        expected[i] = expected[node.left()];
        expected[i].extend(expected[node.right()]);
      }
    }
    for (size_t i = 0; i < expected.size(); ++i) {
      ASSERT_EQ(from_mesh.nodes[i].bounds_min, expected[i].min) << builder_name(builder) << " node " << i;
      ASSERT_EQ(from_mesh.nodes[i].bounds_max, expected[i].max) << builder_name(builder) << " node " << i;
    }
    EXPECT_EQ(0, std::memcmp(from_mesh.nodes.data(), from_boxes.nodes.data(), from_mesh.nodes.size() * sizeof(BvhNode)));
  }
}

// The same tree with its nodes in breadth-first order: children still after parents (all refit
// asks of a caller's BVH), but a subtree's descendants no longer contiguous. to_bfs[old] = new index.
Bvh breadth_first(const Bvh& bvh, std::vector<uint32_t>& to_bfs) {
  Bvh bfs = bvh;
  to_bfs.assign(bvh.nodes.size(), 0);
  std::vector<uint32_t> order{0};  // old indices in breadth-first order
  for (size_t next = 0; next < order.size(); ++next) {
    const BvhNode& node = bvh.nodes[order[next]];
    to_bfs[order[next]] = static_cast<uint32_t>(next);
    if (node.is_leaf()) continue;
    order.push_back(node.left());
    order.push_back(node.right());
  }
  for (size_t i = 0; i < order.size(); ++i) {
    BvhNode node = bvh.nodes[order[i]];
    if (!node.is_leaf()) node.first = to_bfs[node.left()];
    bfs.nodes[i] = node;
  }
  return bfs;
}

TEST(ParallelRefit, AnotherNodeOrderIsRefittedByOneSweepAndABrokenOneIsAClearError) {
  testing::TestMesh mesh = testing::make_clustered(14, 30000);
  Bvh bvh = build_bvh(BvhBuilder::sah, mesh.view());
  std::vector<uint32_t> to_bfs;
  Bvh bfs = breadth_first(bvh, to_bfs);
  ASSERT_NE(0, std::memcmp(bfs.nodes.data(), bvh.nodes.data(), bvh.nodes.size() * sizeof(BvhNode)));
  deform(mesh, 0.05f);
  refit(bvh, mesh.view());
  refit(bfs, mesh.view());
  for (size_t i = 0; i < bvh.nodes.size(); ++i) {
    ASSERT_EQ(bfs.nodes[to_bfs[i]].bounds_min, bvh.nodes[i].bounds_min) << "node " << i;
    ASSERT_EQ(bfs.nodes[to_bfs[i]].bounds_max, bvh.nodes[i].bounds_max) << "node " << i;
  }
  // A child before its parent (here: the last interior node points back at the root's pair).
  for (size_t i = bfs.nodes.size(); i-- > 0;) {
    if (bfs.nodes[i].is_leaf()) continue;
    bfs.nodes[i].first = 1;
    break;
  }
  EXPECT_THROW(refit(bfs, mesh.view()), Error);
}

TEST(ParallelRefit, WideBoxesAndBlocksEqualASerialRecomputation) {
  testing::TestMesh mesh = testing::make_clustered(13, 60000);
  WideBvh8 wide = collapse_to_wide<8>(build_bvh(BvhBuilder::sah, mesh.view()), mesh.view());
  deform(mesh, 0.05f);
  refit(wide, mesh.view());
  const TriangleMesh view = mesh.view();
  // Every lane's box recomputed by a serial recursion from the moved triangles.
  const auto subtree_box = [&](auto& self, uint32_t index) -> Aabb {
    Aabb box;
    const WideNode<8>& node = wide.nodes[index];
    for (int lane = 0; lane < 8; ++lane) {
      if (node.is_empty(lane)) continue;
      Aabb lane_box;
      if (node.is_leaf(lane)) {
        for (uint32_t slot = 0; slot < node.prim_count[lane]; ++slot) {
          const TriangleBlock<8>& block = wide.blocks[node.child[lane] + slot / 8];
          const Triangle tri = view.triangle(block.prim[slot % 8]);
          lane_box.extend(tri.bounds());
          EXPECT_EQ(block.v[0][0][slot % 8], tri.v0.x);
          EXPECT_EQ(block.v[2][2][slot % 8], tri.v2.z);
        }
      } else {
        lane_box = self(self, node.child[lane]);
      }
      EXPECT_EQ(node.child_bounds(lane).min, lane_box.min) << "node " << index << " lane " << lane;
      EXPECT_EQ(node.child_bounds(lane).max, lane_box.max) << "node " << index << " lane " << lane;
      box.extend(lane_box);
    }
    return box;
  };
  const Aabb root = subtree_box(subtree_box, 0);
  EXPECT_EQ(wide.bounds.min, root.min);
  EXPECT_EQ(wide.bounds.max, root.max);
}

}  // namespace
}  // namespace glint::accel
