#include "accel/builders/radix_sort.h"
#include "core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace glint::accel {
namespace {

// Random keys of key_bits bits drawn from a pool of `distinct` values, so duplicates are common.
std::vector<uint64_t> random_keys(uint32_t seed, size_t count, uint32_t key_bits, size_t distinct) {
  std::mt19937_64 rng(seed);
  const uint64_t mask = key_bits == 64 ? ~uint64_t{0} : (uint64_t{1} << key_bits) - 1;
  std::vector<uint64_t> pool(distinct);
  for (uint64_t& key : pool) key = rng() & mask;
  std::vector<uint64_t> keys(count);
  for (uint64_t& key : keys) key = pool[rng() % distinct];
  return keys;
}

TEST(RadixSort, MatchesStdSortAndIsStable) {
  for (const uint32_t key_bits : {8u, 30u, 63u, 64u}) {
    for (const size_t count : {size_t{0}, size_t{1}, size_t{2}, size_t{1000}, size_t{100003}}) {
      for (const size_t distinct : {size_t{1}, size_t{7}, size_t{50000}}) {
        std::vector<uint64_t> keys = random_keys(key_bits * 1000 + static_cast<uint32_t>(count), count, key_bits, distinct);
        std::vector<uint32_t> values(count);
        std::iota(values.begin(), values.end(), 0u);
        std::vector<std::pair<uint64_t, uint32_t>> expected(count);
        for (size_t i = 0; i < count; ++i) expected[i] = {keys[i], values[i]};
        // Values start as the positions, so a stable sort is the sort by (key, value).
        std::sort(expected.begin(), expected.end());

        radix_sort_pairs(keys, values, key_bits);
        ASSERT_EQ(keys.size(), count);
        for (size_t i = 0; i < count; ++i) {
          ASSERT_EQ(keys[i], expected[i].first) << "bits " << key_bits << " count " << count << " at " << i;
          ASSERT_EQ(values[i], expected[i].second) << "bits " << key_bits << " count " << count << " at " << i;
        }
      }
    }
  }
}

TEST(RadixSort, ByBitsOrdersByThoseBitsAloneAndIsStable) {
  for (const auto& [low, high] : {std::pair{33u, 64u}, std::pair{0u, 33u}, std::pair{5u, 12u}, std::pair{60u, 64u}}) {
    std::vector<uint64_t> keys = random_keys(low * 100 + high, 50000, 64, 20000);
    std::vector<uint32_t> values(keys.size());
    std::iota(values.begin(), values.end(), 0u);
    const auto bits_of = [&](uint64_t key) {
      const uint64_t below_high = high == 64 ? key : key & ((uint64_t{1} << high) - 1);
      return below_high >> low;
    };
    std::vector<std::pair<uint64_t, uint32_t>> expected;
    for (size_t i = 0; i < keys.size(); ++i) expected.emplace_back(keys[i], values[i]);
    std::stable_sort(expected.begin(), expected.end(), [&](const auto& a, const auto& b) {
      return bits_of(a.first) < bits_of(b.first);
    });
    radix_sort_pairs_by_bits(keys, values, low, high);
    for (size_t i = 0; i < keys.size(); ++i) {
      ASSERT_EQ(keys[i], expected[i].first) << "bits [" << low << ", " << high << ") at " << i;
      ASSERT_EQ(values[i], expected[i].second) << "bits [" << low << ", " << high << ") at " << i;
    }
  }
  std::vector<uint64_t> keys(4);
  std::vector<uint32_t> values(4);
  EXPECT_THROW(radix_sort_pairs_by_bits(keys, values, 10, 10), Error);
  EXPECT_THROW(radix_sort_pairs_by_bits(keys, values, 0, 65), Error);
}

TEST(RadixSort, SkewedKeysWithOneHugeBucketAndManyTinyOnes) {
  // Long inputs are sorted by their top 8 bits first, then bucket by bucket: here one bucket holds
  // most keys (sorted by the parallel sort again), the others a handful each (insertion sort).
  std::mt19937_64 rng(11);
  std::vector<uint64_t> keys(300000);
  for (uint64_t& key : keys) {
    const uint64_t low = rng() & ((uint64_t{1} << 40) - 1);
    key = (rng() % 5 != 0 ? uint64_t{0x5a} << 40 : (rng() & 0xff) << 40) | (low % 1000003);
  }
  std::vector<uint32_t> values(keys.size());
  std::iota(values.begin(), values.end(), 0u);
  std::vector<std::pair<uint64_t, uint32_t>> expected;
  for (size_t i = 0; i < keys.size(); ++i) expected.emplace_back(keys[i], values[i]);
  std::sort(expected.begin(), expected.end());
  radix_sort_pairs(keys, values, 48);
  for (size_t i = 0; i < keys.size(); ++i) {
    ASSERT_EQ(keys[i], expected[i].first) << "at " << i;
    ASSERT_EQ(values[i], expected[i].second) << "at " << i;
  }
}

TEST(RadixSort, VisitedRangesCoverTheArrayAreSortedWhenVisitedAndKeepEqualKeysTogether) {
  for (const size_t count : {size_t{1000}, size_t{300000}}) {  // LSD passes; bucket by bucket
    std::mt19937_64 rng(count);
    std::vector<uint64_t> keys(count);
    // Bits [33, 64) sort; a quarter of the keys share one top byte (a bucket sorted in parallel).
    for (uint64_t& key : keys) key = (rng() % 4 == 0 ? uint64_t{0x5a} << 56 : rng() & (uint64_t{0xff} << 56)) | (rng() % 5000) << 33 | (rng() & 0xffff);
    std::vector<uint32_t> values(count);
    std::iota(values.begin(), values.end(), 0u);
    std::mutex mutex;
    std::vector<std::pair<size_t, size_t>> ranges;
    bool sorted_when_visited = true;
    radix_sort_pairs_by_bits(keys, values, 33, 64, [&](size_t begin, size_t end) {
      const bool sorted = std::is_sorted(keys.begin() + begin, keys.begin() + end,
                                         [](uint64_t a, uint64_t b) { return a >> 33 < b >> 33; });
      const std::lock_guard lock(mutex);
      sorted_when_visited = sorted_when_visited && sorted;
      ranges.emplace_back(begin, end);
    });
    EXPECT_TRUE(sorted_when_visited) << count;
    std::sort(ranges.begin(), ranges.end());
    ASSERT_FALSE(ranges.empty());
    EXPECT_EQ(ranges.front().first, 0u);
    EXPECT_EQ(ranges.back().second, count);
    for (size_t i = 0; i < ranges.size(); ++i) {
      EXPECT_LT(ranges[i].first, ranges[i].second);
      if (i > 0) {
        EXPECT_EQ(ranges[i].first, ranges[i - 1].second);
        EXPECT_NE(keys[ranges[i].first] >> 33, keys[ranges[i].first - 1] >> 33) << "equal keys straddle two ranges";
      }
    }
    if (count > 100000) {
      EXPECT_GT(ranges.size(), 1u);
    }
    EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end(), [](uint64_t a, uint64_t b) { return a >> 33 < b >> 33; }));
  }
}

TEST(RadixSort, SortedAndReversedInputs) {
  std::vector<uint64_t> keys(70000);
  std::iota(keys.begin(), keys.end(), uint64_t{1} << 40);
  std::reverse(keys.begin(), keys.end());
  std::vector<uint32_t> values(keys.size());
  std::iota(values.begin(), values.end(), 0u);
  radix_sort_pairs(keys, values, 41);
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
  for (size_t i = 0; i < values.size(); ++i) ASSERT_EQ(values[i], values.size() - 1 - i);
  radix_sort_pairs(keys, values, 41);  // already sorted: nothing moves
  EXPECT_TRUE(std::is_sorted(keys.begin(), keys.end()));
  EXPECT_EQ(values.front(), values.size() - 1);
}

TEST(RadixSort, BadArgumentsAreClearErrors) {
  std::vector<uint64_t> keys(3, 1);
  std::vector<uint32_t> values(2, 0);
  EXPECT_THROW(radix_sort_pairs(keys, values, 30), Error);
  values.resize(3);
  EXPECT_THROW(radix_sort_pairs(keys, values, 0), Error);
  EXPECT_THROW(radix_sort_pairs(keys, values, 65), Error);
}

}  // namespace
}  // namespace glint::accel
