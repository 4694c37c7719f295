// UnzeroedVector (Bvh's arrays): a std::vector in every way but value-initialisation and the
// alignment of large arrays. What resize(n) leaves in the new elements is unspecified, so the
// tests only check what must hold.
#include "accel/bvh.h"
#include "accel/unzeroed_vector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>

namespace glint::accel {
namespace {

TEST(UnzeroedVector, LargeArraysAreHugePageAligned) {
  UnzeroedVector<BvhNode> nodes;
  nodes.resize(detail::kHugePageMinBytes / sizeof(BvhNode));
  EXPECT_EQ(reinterpret_cast<uintptr_t>(nodes.data()) % detail::kHugePageBytes, 0u);
  UnzeroedVector<uint32_t> small(100);
  EXPECT_EQ(reinterpret_cast<uintptr_t>(small.data()) % alignof(std::max_align_t), 0u);
}

TEST(UnzeroedVector, EverythingButValueInitialisationConstructsAsUsual) {
  BvhNode node;
  node.first = 7;
  node.prim_count = 3;
  node.bounds_max = vec3(1.0f, 2.0f, 3.0f);
  UnzeroedVector<BvhNode> nodes(5, node);
  nodes.push_back(BvhNode{});
  nodes.resize(8, node);
  ASSERT_EQ(nodes.size(), 8u);
  for (size_t i : {0u, 4u, 6u, 7u}) {
    EXPECT_EQ(nodes[i].first, 7u);
    EXPECT_EQ(nodes[i].bounds_max, vec3(1.0f, 2.0f, 3.0f));
  }
  EXPECT_EQ(nodes[5].first, 0u);  // BvhNode{} is zero
  EXPECT_EQ(nodes[5].prim_count, 0u);

  // Written after resize(n), then copied and grown: the values survive every reallocation.
  UnzeroedVector<uint32_t> values;
  values.resize(1000);
  std::iota(values.begin(), values.end(), 0u);
  const UnzeroedVector<uint32_t> copy = values;
  values.resize(3000000);  // reallocates into huge-page storage
  for (uint32_t i = 0; i < 1000; ++i) {
    ASSERT_EQ(values[i], i);
    ASSERT_EQ(copy[i], i);
  }
  EXPECT_TRUE(std::equal(copy.begin(), copy.end(), values.begin()));
}

}  // namespace
}  // namespace glint::accel
