#pragma once
// Internal to the top-down builders: splitting a range of references in two by a predicate on the
// reference, computing both children's bounds in the same pass (so no extra pass over the children
// is needed to start splitting them). Two ways, chosen by the caller:
//  - in place, one thread, not stable (Hoare's two pointers): small ranges;
//  - parallel and stable, from one reference array into another at the same positions: large ranges,
//    where one thread partitioning 600k references is the builder's serial bottleneck. Blocks of
//    `chunk` references count their left ones (or the caller knows the counts from binning), a
//    prefix sum over the blocks gives each block its output offsets, and the blocks scatter in
//    parallel, bounding both sides as they go. The output does not depend on the number of threads.
// Both put exactly the references with goes_left(ref) first and give the same bounds; only the
// order inside each side differs.
#include "accel/builders/prim_ref.h"

#include <tbb/parallel_for.h>

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace glint::accel::detail {

// The two children of a split range, with their bounds, and whether their references were moved to
// the builder's other reference array (same positions).
struct Split {
  PrimRange left;
  PrimRange right;
  bool moved = false;
};

template <typename GoesLeft>
Split partition_in_place(std::span<PrimRef> refs, const PrimRange& range, GoesLeft&& goes_left) {
  RangeBounds left_bounds, right_bounds;
  uint32_t l = range.begin, r = range.end;
  for (;;) {
    while (l < r && goes_left(refs[l])) left_bounds.extend(refs[l++]);
    while (l < r && !goes_left(refs[r - 1])) right_bounds.extend(refs[--r]);
    if (l == r) break;
    // refs[l] belongs right and refs[r - 1] left, so they are two different references.
    std::swap(refs[l], refs[r - 1]);
    left_bounds.extend(refs[l++]);
    right_bounds.extend(refs[--r]);
  }
  Split split{{range.begin, l, {}, {}}, {l, range.end, {}, {}}, false};
  left_bounds.write(split.left);
  right_bounds.write(split.right);
  return split;
}

// left_counts: when the caller already knows how many references of each block go left (binning
// recorded it, BlockBinCounts), the counting pass is skipped; otherwise empty.
template <typename GoesLeft>
Split partition_parallel(std::span<const PrimRef> from, std::span<PrimRef> to, const PrimRange& range, uint32_t chunk,
                         GoesLeft&& goes_left, std::span<const uint32_t> left_counts = {}) {
  struct Block {
    uint32_t left_count = 0;
    uint32_t left_at = 0;  // output slots, filled by the prefix sum
    uint32_t right_at = 0;
    RangeBounds left, right;
  };
  const uint32_t blocks = (range.size() + chunk - 1) / chunk;
  const auto block_limits = [&](uint32_t b) {
    return std::pair{range.begin + b * chunk, b + 1 == blocks ? range.end : range.begin + (b + 1) * chunk};
  };
  std::vector<Block> block(blocks);  // one allocation per large node, none per primitive
  if (left_counts.empty()) {
    tbb::parallel_for(uint32_t{0}, blocks, [&](uint32_t b) {
      const auto [begin, end] = block_limits(b);
      uint32_t count = 0;
      for (uint32_t i = begin; i != end; ++i) count += goes_left(from[i]) ? 1 : 0;
      block[b].left_count = count;
    });
  } else {
    for (uint32_t b = 0; b < blocks; ++b) block[b].left_count = left_counts[b];
  }

  uint32_t left_total = 0;
  for (const Block& b : block) left_total += b.left_count;
  uint32_t left_at = range.begin, right_at = range.begin + left_total;
  for (uint32_t b = 0; b < blocks; ++b) {
    const auto [begin, end] = block_limits(b);
    block[b].left_at = left_at;
    block[b].right_at = right_at;
    left_at += block[b].left_count;
    right_at += (end - begin) - block[b].left_count;
  }

  // Each block bounds what it scatters, in order; the blocks' bounds are merged in block order, so
  // the children's boxes do not depend on which thread ran which block.
  tbb::parallel_for(uint32_t{0}, blocks, [&](uint32_t b) {
    Block& out = block[b];
    uint32_t l = out.left_at, r = out.right_at;
    const auto [begin, end] = block_limits(b);
    for (uint32_t i = begin; i != end; ++i) {
      if (goes_left(from[i])) {
        out.left.extend(from[i]);
        to[l++] = from[i];
      } else {
        out.right.extend(from[i]);
        to[r++] = from[i];
      }
    }
  });

  Split split{{range.begin, range.begin + left_total, {}, {}}, {range.begin + left_total, range.end, {}, {}}, true};
  RangeBounds left_bounds, right_bounds;
  for (const Block& b : block) {
    left_bounds.extend(b.left);
    right_bounds.extend(b.right);
  }
  left_bounds.write(split.left);
  right_bounds.write(split.right);
  return split;
}

}  // namespace glint::accel::detail
