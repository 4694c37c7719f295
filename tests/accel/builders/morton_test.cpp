#include "accel/builders/morton.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numeric>
#include <random>
#include <span>
#include <utility>
#include <vector>

namespace glint::accel {
namespace {

// Bit by bit: bit b of axis a goes to bit 3b + a.
uint64_t interleave_slowly(uint32_t x, uint32_t y, uint32_t z, uint32_t bits) {
  uint64_t code = 0;
  for (uint32_t b = 0; b < bits; ++b) {
    code |= uint64_t{(x >> b) & 1u} << (3 * b);
    code |= uint64_t{(y >> b) & 1u} << (3 * b + 1);
    code |= uint64_t{(z >> b) & 1u} << (3 * b + 2);
  }
  return code;
}

TEST(Morton, TheCpuTableVersionOfMorton63GivesTheSameBits) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<float> wide(-0.25f, 1.25f);  // clamping on both sides included
  std::uniform_int_distribution<uint32_t> cell21(0, (1u << 21) - 1);
  for (int i = 0; i < 200000; ++i) {
    const vec3 p(wide(rng), wide(rng), wide(rng));
    ASSERT_EQ(detail::morton63_by_table(p), morton63(p)) << p.x << " " << p.y << " " << p.z;
    const vec3 cells(static_cast<float>(cell21(rng)), static_cast<float>(cell21(rng)), static_cast<float>(cell21(rng)));
    const vec3 unit = (cells + 0.5f) / 2097152.0f;
    ASSERT_EQ(detail::morton63_by_table(unit), morton63(unit));
  }
  for (const float edge : {0.0f, 1.0f, -0.0f, 0.5f, std::nextafter(1.0f, 0.0f), std::numeric_limits<float>::quiet_NaN()})
    EXPECT_EQ(detail::morton63_by_table(vec3(edge)), morton63(vec3(edge))) << edge;
}

TEST(Morton, CodesInterleaveTheQuantisedCoordinates) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<uint32_t> cell10(0, 1023), cell21(0, (1u << 21) - 1);
  for (int i = 0; i < 2000; ++i) {
    const uint32_t x = cell10(rng), y = cell10(rng), z = cell10(rng);
    // Cell centres, so the float conversion cannot land on a neighbour.
    const vec3 unit = (vec3(static_cast<float>(x), static_cast<float>(y), static_cast<float>(z)) + 0.5f) / 1024.0f;
    ASSERT_EQ(morton30(unit), interleave_slowly(x, y, z, 10));
    const uint32_t x21 = cell21(rng), y21 = cell21(rng), z21 = cell21(rng);
    const vec3 unit21 =
        (vec3(static_cast<float>(x21), static_cast<float>(y21), static_cast<float>(z21)) + 0.5f) / 2097152.0f;
    ASSERT_EQ(morton63(unit21), interleave_slowly(x21, y21, z21, 21));
  }
  EXPECT_EQ(morton30(vec3(0.0f)), 0u);
  EXPECT_EQ(morton30(vec3(1.0f)), (1u << 30) - 1);  // the top cell is closed
  EXPECT_EQ(morton63(vec3(1.0f)), (uint64_t{1} << 63) - 1);
  EXPECT_EQ(morton30(vec3(-5.0f, 2.0f, 0.0f)), morton30(vec3(0.0f, 1.0f, 0.0f)));  // clamped
  EXPECT_EQ(morton30(vec3(1.5f / 1024.0f, 0.0f, 0.0f)), 1u);
  EXPECT_EQ(morton30(vec3(0.0f, 1.5f / 1024.0f, 0.0f)), 2u);
  EXPECT_EQ(morton30(vec3(0.0f, 0.0f, 1.5f / 1024.0f)), 4u);
}

TEST(Morton, SortFollowsTheZCurve) {
  // The 8 octant centres of a cube, shuffled: the Z curve visits x first, then y, then z.
  std::vector<vec3> centroids;
  for (int i = 0; i < 8; ++i)
    centroids.push_back(vec3(i & 1 ? 0.75f : 0.25f, i & 2 ? 0.75f : 0.25f, i & 4 ? 0.75f : 0.25f));
  const std::vector<int> shuffle{5, 2, 7, 0, 3, 6, 1, 4};
  std::vector<vec3> shuffled;
  for (const int i : shuffle) shuffled.push_back(centroids[static_cast<size_t>(i)]);
  const MortonOrder order = sort_by_morton(shuffled);
  ASSERT_EQ(order.prims.size(), 8u);
  EXPECT_EQ(order.bits, 30u);
  for (int rank = 0; rank < 8; ++rank)
    EXPECT_EQ(shuffle[order.prims[static_cast<size_t>(rank)]], rank) << "rank " << rank;
  EXPECT_TRUE(std::is_sorted(order.codes.begin(), order.codes.end()));
}

TEST(Morton, SixtyThreeBitsSeparateWhatThirtyBitsCannot) {
  const vec3 a(0.5f, 0.5f, 0.5f), b(0.5f + 1e-4f, 0.5f, 0.5f);  // 1e-4 apart: one 30-bit cell
  EXPECT_EQ(morton30(a), morton30(b));
  EXPECT_LT(morton63(a), morton63(b));

  // A dense cluster in a large box (1e-5 apart: within a 30-bit cell of 1/1024, but 20 cells of
  // 2^-21 apart): most 30-bit codes collide, so the sort switches to 63 bits and orders the cluster
  // along x.
  std::vector<vec3> centroids{vec3(0.0f), vec3(1.0f)};
  for (int i = 0; i < 1000; ++i) centroids.push_back(vec3(0.5f + static_cast<float>(i) * 1e-5f, 0.5f, 0.5f));
  std::reverse(centroids.begin() + 2, centroids.end());
  const MortonOrder fine = sort_by_morton(centroids);
  EXPECT_EQ(fine.bits, 63u);
  EXPECT_TRUE(std::is_sorted(fine.codes.begin(), fine.codes.end()));
  for (size_t rank = 1; rank + 1 < fine.prims.size(); ++rank)  // the cluster, between the corners
    EXPECT_LT(centroids[fine.prims[rank]].x, centroids[fine.prims[rank + 1]].x) << "rank " << rank;

  // Identical centroids collide in any code length: they do not ask for 63 bits.
  std::vector<vec3> same{vec3(0.0f), vec3(1.0f)};
  same.resize(1002, vec3(0.5f));
  const MortonOrder coarse = sort_by_morton(same);
  EXPECT_EQ(coarse.bits, 30u);
  for (size_t rank = 1; rank + 2 < coarse.prims.size(); ++rank)  // equal codes keep index order
    EXPECT_LT(coarse.prims[rank], coarse.prims[rank + 1]);
}

TEST(Morton, TheTopThirtyOfSixtyThreeBitsAreTheThirtyBitCode) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> unit(-0.1f, 1.1f);  // some outside, to cover the clamping
  for (int i = 0; i < 100000; ++i) {
    const vec3 p(unit(rng), unit(rng), unit(rng));
    ASSERT_EQ(morton63(p) >> 33, uint64_t{morton30(p)}) << p.x << " " << p.y << " " << p.z;
  }
  for (const float edge : {0.0f, 1.0f, 1023.0f / 1024.0f, std::nextafter(1023.0f / 1024.0f, 0.0f), 0.5f})
    EXPECT_EQ(morton63(vec3(edge)) >> 33, uint64_t{morton30(vec3(edge))}) << edge;
}

// The order sort_by_morton must give, by brute force: stable by code, 30 or 63 bits.
std::vector<uint32_t> stable_order(std::span<const vec3> centroids, uint32_t bits) {
  Aabb box;
  for (const vec3& c : centroids) box.extend(c);
  const vec3 scale = unit_cube_scale(box.extent());
  std::vector<uint64_t> codes;
  for (const vec3& c : centroids) {
    const vec3 unit = (c - box.min) * scale;
    codes.push_back(bits == 30 ? uint64_t{morton30(unit)} : morton63(unit));
  }
  std::vector<uint32_t> prims(centroids.size());
  std::iota(prims.begin(), prims.end(), 0u);
  std::stable_sort(prims.begin(), prims.end(), [&](uint32_t a, uint32_t b) { return codes[a] < codes[b]; });
  return prims;
}

TEST(Morton, SortEqualsAStableSortByTheChosenCode) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // Points packed into one 30-bit cell each run, with distinct 63-bit codes.
  const auto add_runs = [&](std::vector<vec3>& points, std::initializer_list<int> runs) {
    for (const int run : runs) {
      const vec3 cell(unit(rng), unit(rng), unit(rng));
      for (int i = 0; i < run; ++i) points.push_back(cell + vec3(unit(rng), unit(rng), unit(rng)) * 1e-4f);
    }
  };
  // Spread points with a few runs, under 1 % of collisions: 30 bits win, and the runs, which the
  // sort refines to 63 bits as it goes, must be put back in index order (both by insertion sort
  // and, over 64, by a sort of their own). More than 65,536 points, so the radix sort goes bucket
  // by bucket.
  std::vector<vec3> spread(100000);
  for (vec3& p : spread) p = vec3(unit(rng), unit(rng), unit(rng));
  add_runs(spread, {2, 2, 3, 5, 17, 64, 300});
  std::shuffle(spread.begin(), spread.end(), rng);
  // Clustered points, whose runs of equal 30-bit codes have every length: short ones (insertion
  // sort) and long ones (radix sort), among spread ones.
  std::vector<vec3> clustered{vec3(0.0f), vec3(1.0f)};
  for (int i = 0; i < 30000; ++i) clustered.push_back(vec3(unit(rng), unit(rng), unit(rng)));
  add_runs(clustered, {2, 3, 40, 64, 65, 300, 5000, 40000});
  std::shuffle(clustered.begin(), clustered.end(), rng);
  for (const auto& [centroids, bits] : {std::pair{spread, 30u}, std::pair{clustered, 63u}}) {
    const MortonOrder order = sort_by_morton(centroids);
    EXPECT_EQ(order.bits, bits);
    EXPECT_EQ(std::vector<uint32_t>(order.prims.begin(), order.prims.end()), stable_order(centroids, bits));
    EXPECT_TRUE(std::is_sorted(order.codes.begin(), order.codes.end()));
    if (bits == 30) {
      EXPECT_LT(*std::max_element(order.codes.begin(), order.codes.end()), uint64_t{1} << 30);
    }
  }
}

TEST(Morton, FlatAxesAndBadCentroids) {
  const std::vector<vec3> flat{vec3(3.0f, 1.0f, 2.0f), vec3(1.0f, 1.0f, 2.0f), vec3(2.0f, 1.0f, 2.0f)};
  const MortonOrder order = sort_by_morton(flat);
  EXPECT_EQ(std::vector<uint32_t>(order.prims.begin(), order.prims.end()), (std::vector<uint32_t>{1, 2, 0}));
  std::vector<vec3> bad = flat;
  bad[1].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(sort_by_morton(bad), Error);
  bad[1].y = std::numeric_limits<float>::infinity();
  EXPECT_THROW(sort_by_morton(bad), Error);
  EXPECT_TRUE(sort_by_morton({}).prims.empty());
}

}  // namespace
}  // namespace glint::accel
