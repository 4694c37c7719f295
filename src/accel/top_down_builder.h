#pragma once
// Internal to the builders: the recursive top-down skeleton shared by build_median and build_sah
// (and later sbvh/kdtree-style splitters). A builder only decides where to split a range of
// primitives; this file owns node allocation, leaves, the depth limit, TBB task parallelism on the
// large top levels, timing, and the final deterministic node order.
#include "accel/build_options.h"
#include "accel/bvh.h"

#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace glint::accel::detail {

// A contiguous range [begin, end) of Bvh::prim_indices and the boxes of what it holds.
struct PrimRange {
  uint32_t begin = 0;
  uint32_t end = 0;
  Aabb box;           // union of the primitive boxes
  Aabb centroid_box;  // bounds of the centroids

  uint32_t size() const { return end - begin; }
};

// Context handed to a split policy.
struct SplitContext {
  const BuildInput& input;
  const BuildOptions& options;
  std::span<uint32_t> prim_indices;  // the whole permutation; a policy reorders only its range
  bool parallel;                     // the range is large enough to use TBB inside the policy
};

// A split policy reorders prim_indices[range] and returns the split point mid (begin < mid < end),
// or nullopt to ask for a leaf. The skeleton makes a leaf only when the range fits in
// max_leaf_size; otherwise (or when the policy's split would break the depth limit) it falls back to
// object_median_split, which always succeeds.
using SplitPolicy = std::optional<uint32_t> (*)(const SplitContext& context, const PrimRange& range);

// Object median on the longest centroid axis; when all centroids coincide, splits the range in
// half as it is (any order is as good as another).
uint32_t object_median_split(const SplitContext& context, const PrimRange& range);

// Union of boxes and of centroids over prim_indices[begin, end), in parallel when asked.
PrimRange bound_range(const BuildInput& input, std::span<const uint32_t> prim_indices, uint32_t begin, uint32_t end,
                      bool parallel);

// Validates input and options (glint::Error on mismatch), runs the recursion, lays the nodes out in
// a deterministic depth-first order (sibling pairs adjacent, children after parents) and times it.
Bvh build_top_down(const BuildInput& input, const BuildOptions& options, const std::string& name, SplitPolicy policy);

}  // namespace glint::accel::detail
