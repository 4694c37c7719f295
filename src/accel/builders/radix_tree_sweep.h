#pragma once
// Internal to lbvh and trbvh: the Karras 2012 radix tree over sorted Morton codes, built bottom-up
// in one parallel sweep as in Apetrei 2014, "Fast and simple agglomerative LBVH construction". The
// sweep says which node joins which; the caller decides what a node stores (build_lbvh.cpp keeps a
// full BinaryTree for trbvh, and a leafless RadixTree for lbvh itself).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <bit>
#include <cstdint>
#include <span>

#include "accel/builders/build_options.h"
#include "accel/builders/parallel_array.h"

namespace glint::accel::detail {

// Keys ahead whose boxes the sweeps prefetch: the boxes are read in Morton order, so at random, and
// fetching a few keys ahead hides the cache misses that were a third of a sweep.
inline constexpr uint32_t kBoxPrefetchDistance = 16;

// Prefetches the box of the primitive kBoxPrefetchDistance keys after `key` (prims: the Morton order).
inline void prefetch_box_ahead(const BuildInput& input, std::span<const uint32_t> prims, uint32_t key) {
  if (key + kBoxPrefetchDistance < prims.size()) __builtin_prefetch(&input.boxes[prims[key + kBoxPrefetchDistance]]);
}

// Karras's delta(i, j): the length of the common prefix of keys i and j, where a key is the Morton
// code followed by the 32-bit position (so equal codes still differ).
struct CommonPrefix {
  std::span<const uint64_t> codes;

  int operator()(uint32_t i, uint32_t j) const {
    const uint64_t a = codes[i], b = codes[j];
    if (a != b) return std::countl_zero(a ^ b);
    return 64 + std::countl_zero(i ^ j);
  }
};

// Node ids in the sweep: leaf i (the i-th sorted key) is i, and the interior node whose split lies
// between keys b and b + 1 (its left child ends at key b) is leaf_count + b.
//
// Every leaf climbs towards the root; a node covering keys [first, last] joins the neighbour across
// whichever end shares the longer prefix with it. The node's parent is thus known from its range
// alone. The two children of a node meet at an atomic slot: the first to arrive leaves the far end
// of its range and stops, the second takes it and goes on with the union. In a radix tree the
// parent's split shares a longer prefix than the boundary on the node's other side (the keys beyond
// that one lack the parent's prefix), so this is exactly Karras's tree, with no binary searches and
// with each node visited once, after both of its children: boxes and anything else computed
// bottom-up come in the same sweep.
//
// In parallel, calls visit_leaf(leaf) once per leaf, link(child, parent, is_left_child) once per
// node but the root, and visit_interior(node, first, last) once per interior node, with its keys
// [first, last], after both of its children were linked and visited (what they wrote is visible to
// it). Returns the root's id; codes must not
// be empty.
template <typename VisitLeaf, typename Link, typename VisitInterior>
uint32_t sweep_radix_tree(std::span<const uint64_t> codes, VisitLeaf&& visit_leaf, Link&& link,
                          VisitInterior&& visit_interior) {
  const auto count = static_cast<uint32_t>(codes.size());
  if (count == 1) {
    visit_leaf(0u);
    return 0;
  }
  // Far end + 1 of the first child to arrive, 0 while none has (value-initialised in parallel).
  ParallelArray<uint32_t> waiting(count - 1);
  const CommonPrefix delta{codes};
  const uint32_t last_key = count - 1;
  std::atomic<uint32_t> root{0};
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, 512), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t leaf = r.begin(); leaf != r.end(); ++leaf) {
      visit_leaf(leaf);
      uint32_t node = leaf, first = leaf, last = leaf;
      while (first != 0 || last != last_key) {
        const bool is_left_child = first == 0 || (last != last_key && delta(last, last + 1) > delta(first - 1, first));
        const uint32_t split = is_left_child ? last : first - 1;
        const uint32_t parent = count + split;
        link(node, parent, is_left_child);
        // The second arrival must see everything the first one wrote below the parent (acquire,
        // against the first one's release). A sibling already there is seen by a plain acquire
        // load, with no locked instruction: a right child usually finds its left sibling done, as
        // leaves are taken left to right. Otherwise the exchange decides who goes on.
        const uint32_t far_end = is_left_child ? first : last;
        std::atomic_ref<uint32_t> slot(waiting[split]);
        uint32_t sibling_far_end = slot.load(std::memory_order_acquire);
        if (sibling_far_end == 0) {
          sibling_far_end = slot.exchange(far_end + 1, std::memory_order_acq_rel);
          if (sibling_far_end == 0) break;
        }
        (is_left_child ? last : first) = sibling_far_end - 1;
        node = parent;
        visit_interior(node, first, last);
      }
      if (first == 0 && last == last_key) root.store(node, std::memory_order_relaxed);
    }
  });
  return root.load(std::memory_order_relaxed);
}

}  // namespace glint::accel::detail
