#pragma once
// Two BVHs that must be the same tree, possibly laid out in a different node order (lbvh's one-pass
// layout against the BinaryTree path's depth-first one).
#include "accel/bvh.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace glint::accel::testing {

// Walks both trees from their roots in step: the same boxes (bit for bit), the same leaves over the
// same prim_indices slots, the same shape, and no node that no parent links to.
inline void expect_same_tree(const Bvh& expected, const Bvh& actual, const std::string& where) {
  ASSERT_EQ(expected.nodes.size(), actual.nodes.size()) << where;
  EXPECT_EQ(expected.depth, actual.depth) << where;
  EXPECT_EQ(expected.prim_indices, actual.prim_indices) << where;
  const auto same_box = [](const BvhNode& a, const BvhNode& b) {
    return std::memcmp(&a.bounds_min, &b.bounds_min, sizeof(a.bounds_min)) == 0 &&
           std::memcmp(&a.bounds_max, &b.bounds_max, sizeof(a.bounds_max)) == 0;
  };
  if (expected.nodes.empty()) return;
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 0u}};
  size_t visited = 0;
  while (!stack.empty()) {
    const auto [e, a] = stack.back();
    stack.pop_back();
    ++visited;
    const BvhNode& x = expected.nodes[e];
    const BvhNode& y = actual.nodes[a];
    ASSERT_TRUE(same_box(x, y)) << where << ": node " << e << " against " << a;
    ASSERT_EQ(x.prim_count, y.prim_count) << where << ": node " << e << " against " << a;
    if (x.is_leaf()) {
      ASSERT_EQ(x.first, y.first) << where << ": leaf " << e << " against " << a;
    } else {
      stack.emplace_back(x.left(), y.left());
      stack.emplace_back(x.right(), y.right());
    }
  }
  EXPECT_EQ(visited, actual.nodes.size()) << where << ": nodes that no parent links to";
}

}  // namespace glint::accel::testing
