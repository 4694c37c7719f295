// The SAH builder's faster paths against their plain counterparts: SSE box areas and the branch-free
// bin mapping against the scalar formulas (edge values included), block-by-block binning against
// plain binning and brute-force per-block counts, and a partition told the blocks' left counts
// against one that counts them itself.
#include "accel/builders/prim_partition.h"
#include "accel/builders/prim_ref.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/builders/sah_binning.h"
#include "accel/builders/sse_box.h"
#include "prim_ref_test_support.h"
#include "accel/test_scenes.h"

#include <gtest/gtest.h>

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

bool same_bits(const vec3& a, const vec3& b) { return std::memcmp(&a, &b, sizeof(vec3)) == 0; }

TEST(SahSseBox, HalfAreaAndExtendEqualTheScalarOnesBitForBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coord(-100.0f, 100.0f);
  for (int trial = 0; trial < 2000; ++trial) {
    Aabb a, b;
    // Some boxes are inverted (empty on one axis), some flat, some hold signed zeros.
    for (int axis = 0; axis < 3; ++axis) {
      a.min[axis] = coord(rng), a.max[axis] = coord(rng);
      b.min[axis] = coord(rng), b.max[axis] = trial % 7 == 0 ? b.min[axis] : coord(rng);
      if (trial % 11 == 0) a.min[axis] = -0.0f, b.min[axis] = 0.0f;
    }
    detail::SseBox sa = detail::SseBox::of(a);
    EXPECT_EQ(sa.half_area(), half_area(a));
    sa.extend(detail::SseBox::of(b));
    a.extend(b);
    EXPECT_TRUE(same_bits(sa.aabb().min, a.min) && same_bits(sa.aabb().max, a.max));
    EXPECT_EQ(sa.half_area(), half_area(a));
  }
  EXPECT_EQ(detail::SseBox{}.half_area(), 0.0f);
}

TEST(SahBinMapping, BranchFreeBinEqualsTheClampedFormula) {
  const detail::BinMapping mapping{vec3(-1.0f, 0.0f, 2.0f), vec3(4.0f, 0.5f, 16.0f), 16};
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const auto expected = [&](const vec3& c, int axis) -> uint32_t {
    const float position = (c[axis] - mapping.origin[axis]) * mapping.scale[axis];
    if (!(position > 0.0f)) return 0;
    return position < 15.0f ? static_cast<uint32_t>(position) : 15u;
  };
  std::vector<float> values{nan, -inf, inf, -5.0f, -1.0f, -0.0f, 0.0f, 1e-30f, 0.2499f, 0.25f, 1.0f, 2.0f,
                            2.9375f, 3.0f, 3.75f, 31.99f, 32.0f, 33.0f, 1e30f};
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> coord(-2.0f, 40.0f);
  for (int i = 0; i < 5000; ++i) values.push_back(coord(rng));
  for (const float v : values)
    for (int axis = 0; axis < 3; ++axis) {
      const vec3 c(v, v, v);
      EXPECT_EQ(mapping.bin(c, axis), expected(c, axis)) << v << " axis " << axis;
    }
}

TEST(SahBlockBinning, BinsEqualPlainBinningAndBlockCountsEqualBruteForce) {
  const testing::TestMesh scene = testing::make_clustered(5, 60000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  PrimRange root;
  const std::vector<PrimRef> refs = make_refs(bounds, root);
  const PrimRange range = detail::bound_refs(refs, 333, 59000, false, 1024);
  for (const uint32_t bin_count : {2u, 16u, 64u})
    for (const uint32_t chunk : {97u, 4096u}) {
      const std::optional<detail::BinMapping> mapping = detail::bin_mapping(range.centroid_box, bin_count);
      ASSERT_TRUE(mapping);
      detail::SahBins plain, by_block;
      detail::bin_refs(refs, range, *mapping, false, chunk, plain);
      detail::BlockBinCounts counts;
      detail::bin_refs_by_block(refs, range, *mapping, chunk, by_block, counts);
      EXPECT_TRUE(plain == by_block);
      const uint32_t blocks = (range.size() + chunk - 1) / chunk;
      ASSERT_EQ(counts.blocks(), blocks);
      for (uint32_t b = 0; b < blocks; ++b) {
        std::vector<uint32_t> expected(3 * bin_count, 0);
        for (uint32_t i = range.begin + b * chunk; i < std::min(range.end, range.begin + (b + 1) * chunk); ++i)
          for (int axis = 0; axis < 3; ++axis)
            ++expected[static_cast<uint32_t>(axis) * bin_count + mapping->bin(refs[i].centroid, axis)];
        ASSERT_EQ(std::vector<uint32_t>(counts.block(b), counts.block(b) + 3 * bin_count), expected) << "block " << b;
      }
      // Left counts of a boundary are prefix sums of one axis's counts.
      std::vector<uint32_t> left(blocks);
      counts.left_counts(1, bin_count / 2, bin_count, left);
      for (uint32_t b = 0; b < blocks; ++b) {
        uint32_t expected = 0;
        for (uint32_t i = range.begin + b * chunk; i < std::min(range.end, range.begin + (b + 1) * chunk); ++i)
          expected += mapping->bin(refs[i].centroid, 1) < bin_count / 2 ? 1u : 0u;
        EXPECT_EQ(left[b], expected);
      }
    }
}

TEST(SahBlockBinning, PartitionGivenTheLeftCountsEqualsPartitionCountingThem) {
  const testing::TestMesh scene = testing::make_random_soup(8, 40000);
  const PrimitiveBounds bounds = triangle_bounds(scene.view());
  PrimRange root;
  const std::vector<PrimRef> refs = make_refs(bounds, root);
  const PrimRange range = detail::bound_refs(refs, 50, 39000, false, 1024);
  const std::optional<detail::BinMapping> mapping = detail::bin_mapping(range.centroid_box, 16);
  ASSERT_TRUE(mapping);
  const uint32_t chunk = 1000;
  detail::SahBins bins;
  detail::BlockBinCounts counts;
  detail::bin_refs_by_block(refs, range, *mapping, chunk, bins, counts);
  for (int axis = 0; axis < 3; ++axis) {
    const uint32_t boundary = 5 + static_cast<uint32_t>(axis);
    const auto goes_left = [&](const PrimRef& ref) { return mapping->bin(ref.centroid, axis) < boundary; };
    std::vector<uint32_t> left(counts.blocks());
    counts.left_counts(axis, boundary, 16, left);
    std::vector<PrimRef> counted(refs.size()), told(refs.size());
    const detail::Split a = detail::partition_parallel(refs, counted, range, chunk, goes_left);
    const detail::Split b = detail::partition_parallel(refs, told, range, chunk, goes_left, left);
    ASSERT_EQ(a.left.end, b.left.end);
    EXPECT_GT(a.left.size(), 0u);
    EXPECT_GT(a.right.size(), 0u);
    for (uint32_t i = range.begin; i != range.end; ++i) ASSERT_EQ(counted[i].prim, told[i].prim);
    // Bounds: the same as bounding each side afterwards.
    for (const auto& [split, side] : {std::pair{&a, &a.left}, std::pair{&a, &a.right}, std::pair{&b, &b.left}}) {
      (void)split;
      const PrimRange expected = detail::bound_refs(told, side->begin, side->end, false, 1024);
      EXPECT_TRUE(same_bits(side->box.min, expected.box.min) && same_bits(side->box.max, expected.box.max));
      EXPECT_TRUE(same_bits(side->centroid_box.min, expected.centroid_box.min) &&
                  same_bits(side->centroid_box.max, expected.centroid_box.max));
    }
  }
}

}  // namespace
}  // namespace glint::accel
