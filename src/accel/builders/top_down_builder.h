#pragma once
// Internal to the builders: the recursive top-down skeleton shared by build_median and build_sah. A
// builder only decides how to split a range of primitive references; this file owns the references
// (prim_ref.h), node allocation, leaves, the depth limit, timing and the final deterministic node
// order, and the parallelism:
//  - subtrees of at least options.parallel_threshold primitives are built as separate TBB tasks;
//  - inside such large nodes a policy bins, bounds and partitions in parallel (SplitContext::parallel,
//    prim_partition.h), which is what keeps the top levels, where there are fewer subtrees than
//    threads, from running on one thread;
//  - the depth-first renumbering at the end runs as tasks over large subtrees as well.
// The output depends only on the input and the options, not on the number of threads.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"
#include "accel/builders/prim_partition.h"
#include "accel/builders/prim_ref.h"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace glint::accel::detail {

// Context handed to a split policy. The range's references are in refs[range.begin, range.end);
// other[range.begin, range.end) is free for a parallel partition to write the children into.
struct SplitContext {
  const BuildOptions& options;
  std::span<PrimRef> refs;
  std::span<PrimRef> other;
  bool parallel;   // the range is large enough to use TBB inside the policy
  uint32_t chunk;  // references per parallel work item
};

// References per parallel work item inside a node: options.parallel_threshold, clamped so that a
// chunk's bookkeeping stays negligible and a small threshold (tests) still gives many chunks.
uint32_t parallel_chunk(const BuildOptions& options);

// Whether partition_range splits this range in parallel, in blocks of context.chunk references.
inline bool partitions_in_parallel(const SplitContext& context, const PrimRange& range) {
  return context.parallel && range.size() >= 2 * context.chunk;
}

// Splits the range by goes_left(ref) (references with it true first), in parallel into
// context.other for large ranges, in place otherwise; both children's bounds come with it.
// left_counts: for a parallel partition, the number of references of each block that go left, when
// known (see partition_parallel); ignored otherwise.
template <typename GoesLeft>
Split partition_range(const SplitContext& context, const PrimRange& range, GoesLeft&& goes_left,
                      std::span<const uint32_t> left_counts = {}) {
  if (partitions_in_parallel(context, range))
    return partition_parallel(context.refs, context.other, range, context.chunk, goes_left, left_counts);
  return partition_in_place(context.refs, range, goes_left);
}

// A split policy splits the range (partition_range, or in place and bounded by itself) and returns
// its children, or nullopt to ask for a leaf. The skeleton makes a leaf only when the range fits in
// max_leaf_size; otherwise (or when the policy's split is empty on one side or would break the depth
// limit) it falls back to object_median_split, which always succeeds.
using SplitPolicy = std::optional<Split> (*)(const SplitContext& context, const PrimRange& range);

// Object median on the longest centroid axis (ties broken by primitive index, so the halves do not
// depend on the incoming order); when all centroids coincide, splits the range in half as it is.
// In place; the children's bounds in parallel for large ranges.
Split object_median_split(const SplitContext& context, const PrimRange& range);

// Validates input and options (glint::Error on mismatch), runs the recursion, lays the nodes out in
// a deterministic depth-first order (sibling pairs adjacent, children after parents) and times it.
Bvh build_top_down(const BuildInput& input, const BuildOptions& options, const std::string& name, SplitPolicy policy);

}  // namespace glint::accel::detail
