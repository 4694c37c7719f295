#pragma once
// The flat binary BVH node shared by every builder and by CPU and CUDA traversal.
#include "core/math.h"

#include <cstdint>
#include <type_traits>

namespace glint::accel {

// 32 bytes: the box, and either (interior, prim_count == 0) the index of the left child, whose
// sibling is always at left + 1 so one index addresses both; or (leaf, prim_count > 0) the first of
// prim_count consecutive entries of Bvh::prim_indices. Every builder stores children after their
// parent, so a reverse sweep over the array visits children before parents (refit relies on it).
struct BvhNode {
  vec3 bounds_min{0.0f};
  uint32_t first = 0;  // left child (interior) or first prim_indices slot (leaf)
  vec3 bounds_max{0.0f};
  uint32_t prim_count = 0;

  GLINT_HOST_DEVICE bool is_leaf() const { return prim_count != 0; }
  GLINT_HOST_DEVICE uint32_t left() const { return first; }
  GLINT_HOST_DEVICE uint32_t right() const { return first + 1; }
  GLINT_HOST_DEVICE Aabb bounds() const { return Aabb{bounds_min, bounds_max}; }
  GLINT_HOST_DEVICE void set_bounds(const Aabb& box) {
    bounds_min = box.min;
    bounds_max = box.max;
  }
};

static_assert(sizeof(BvhNode) == 32 && alignof(BvhNode) == 4);
static_assert(std::is_trivially_copyable_v<BvhNode>);

// What traversal needs of a BVH, as two pointers: copyable to the device as is once the arrays live
// in device memory. node_count == 0 means an empty structure (every ray misses).
struct BvhView {
  const BvhNode* nodes = nullptr;
  const uint32_t* prim_indices = nullptr;
  uint32_t node_count = 0;
};

static_assert(std::is_trivially_copyable_v<BvhView>);

// Builders never exceed this depth (root = depth 1), so traversal's fixed stack of far children
// never overflows. 64 levels hold far more than 2^32 primitives with a median split.
inline constexpr uint32_t kMaxBvhDepth = 64;

}  // namespace glint::accel
