// The large blocks that builders free are kept for the next arrays they fit (parallel_array.h):
// reused, never handed out twice, bounded in total, and given back on request.
#include "accel/builders/builder.h"
#include "accel/builders/parallel_array.h"
#include "accel/unzeroed_vector.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace glint::accel {
namespace {

using detail::kForOverwrite;
using detail::ParallelArray;
using detail::retained_block_bytes;

constexpr size_t kMiB = size_t{1} << 20;

TEST(RetainedBlocks, AFreedLargeArrayIsReusedByTheNextOneItFits) {
  release_build_memory();
  ASSERT_EQ(retained_block_bytes(), 0u);
  const void* first = nullptr;
  {
    const ParallelArray<uint64_t> array(8 * kMiB / sizeof(uint64_t), kForOverwrite);
    first = array.data();
  }
  EXPECT_EQ(retained_block_bytes(), 8 * kMiB);
  {
    // A little smaller rounds up to the same huge pages: the same block, taken out of the cache.
    const ParallelArray<uint64_t> again(7 * kMiB / sizeof(uint64_t), kForOverwrite);
    EXPECT_EQ(again.data(), first);
    EXPECT_EQ(retained_block_bytes(), 0u);
    // While it is in use, a second array gets a block of its own.
    const ParallelArray<uint64_t> other(8 * kMiB / sizeof(uint64_t), kForOverwrite);
    EXPECT_NE(other.data(), first);
  }
  EXPECT_EQ(retained_block_bytes(), 16 * kMiB);
  // A Bvh's arrays (UnzeroedVector) use the same blocks.
  {
    UnzeroedVector<uint32_t> prims;
    prims.resize(8 * kMiB / sizeof(uint32_t));
    EXPECT_EQ(retained_block_bytes(), 8 * kMiB);
  }
  EXPECT_EQ(retained_block_bytes(), 16 * kMiB);
  release_build_memory();
  EXPECT_EQ(retained_block_bytes(), 0u);
}

TEST(RetainedBlocks, ABlockMoreThanTwiceTooLargeIsLeftForALargerArray) {
  release_build_memory();
  { const ParallelArray<uint8_t> large(20 * kMiB, kForOverwrite); }
  {
    const ParallelArray<uint8_t> small(4 * kMiB, kForOverwrite);
    EXPECT_EQ(retained_block_bytes(), 20 * kMiB);
  }
  EXPECT_EQ(retained_block_bytes(), 24 * kMiB);
  release_build_memory();
}

TEST(RetainedBlocks, SmallArraysAreNotKeptAndTheTotalIsBounded) {
  release_build_memory();
  { const ParallelArray<uint8_t> small(detail::kHugePageMinBytes - 1, kForOverwrite); }
  EXPECT_EQ(retained_block_bytes(), 0u);
  {
    // Never touched, so this costs address space only.
    std::vector<ParallelArray<uint8_t>> arrays;
    for (int i = 0; i < 12; ++i) arrays.emplace_back(32 * kMiB, kForOverwrite);
  }
  EXPECT_LE(retained_block_bytes(), detail::kRetainedBlockBytes);
  EXPECT_GE(retained_block_bytes(), detail::kRetainedBlockBytes - 32 * kMiB);
  release_build_memory();
  EXPECT_EQ(retained_block_bytes(), 0u);
}

TEST(RetainedBlocks, AValueInitialisedArrayIsZeroEvenInAReusedBlock) {
  release_build_memory();
  const size_t count = 8 * kMiB / sizeof(uint32_t);
  {
    ParallelArray<uint32_t> dirty(count, kForOverwrite);
    for (size_t i = 0; i < count; i += 1024) dirty[i] = 0xdeadbeef;
  }
  const ParallelArray<uint32_t> zeroed(count);
  for (size_t i = 0; i < count; i += 1024) ASSERT_EQ(zeroed[i], 0u) << i;
  release_build_memory();
}

}  // namespace
}  // namespace glint::accel
