#pragma once
// Internal to lbvh: Karras's radix tree over sorted Morton codes, its SAH leaf collapsing and its
// flat Bvh layout, made in one sweep over the keys, without an intermediate tree.
//
// Taken left to right by one thread, the keys give the radix tree in post-order, as a stack machine:
// a finished subtree (a key, to start with) that is a left child waits on a stack; a right child
// merges with the stack's top, which is its sibling, and the parent is finished in turn. Which
// side a subtree is on follows from its key range alone (Apetrei 2014: it joins the neighbour across
// the end with the longer common prefix). A merge decides the parent's collapse at once
// (choose_collapse, the rule of SubtreeSummary) and, when the parent stays interior, writes its two children as one sibling
// pair of flat nodes. In post-order a subtree's pairs are the last ones written, so a collapse just
// rewinds the output to where the subtree began. Pairs are written downwards from the end of a
// region, so every parent's pair lies before its children's, as Bvh requires.
//
// In parallel, the keys are cut into chunks of a fixed size (so the layout does not depend on the
// thread count). Each chunk runs the stack machine over its keys, merging only what lies within the
// chunk; what is left, a few dozen finished subtrees per chunk whose parents cross a chunk border,
// goes through the same machine again, in order, by one thread. lay_out_lbvh then copies the pairs
// into one array, depth first (so that refit can cut it into subtrees of contiguous descendants),
// and rebases their child indices: one sequential pass over each chunk's pairs, where a separate
// flattening of a stored tree read every node at random.
#include "accel/builders/binary_tree.h"
#include "accel/builders/build_options.h"
#include "accel/bvh.h"
#include "accel/builders/morton.h"
#include "accel/builders/parallel_array.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::accel::detail {

// Keys per chunk of the sweep for `key_count` keys: about 64 chunks, enough for 16 cores, but at
// least 1,024 keys (below that the subtrees left at the borders, about two per level of a chunk's
// tree, become a noticeable share of the work of the one thread that merges them) and at most
// 8,192 (larger chunks gained nothing). A power of two that depends on the key count alone, so
// the layout does not depend on the thread count.
uint32_t lbvh_chunk_keys(uint32_t key_count);

// A finished subtree of the radix tree over keys [first, last], with what its parent's collapse
// needs (SubtreeSummary's cost and height; its primitives are its keys).
struct LbvhSubtree {
  Aabb box;
  double cost = 0.0;
  uint32_t first = 0;
  uint32_t last = 0;
  uint32_t children = 0;     // where its children's pair was written, unless collapse
  uint32_t pairs_begin = 0;  // the output's pair count when its first key was taken
  uint32_t height = 1;       // levels of its flat subtree
  bool collapse = true;      // one leaf over its keys (a single key always is)
};

// What the sweep wrote for one chunk: pairs numbered 0, 1, ... in the order written, pair k known
// by the id region_end - 2 (k + 1) (chunk c's ids lie in [2 c chunk_keys, region_end), as if it had
// written into a region of its own). They are stored in id order at LbvhSweep::pairs[stored_at, +2
// pair_count). Every subtree the chunk left to the border pass owns a consecutive run of them,
// [begins[i], begins[i + 1]) (the last run ends at pair_count).
struct LbvhChunk {
  uint32_t region_end = 0;
  uint32_t pair_count = 0;
  uint32_t stored_at = 0;
  std::vector<uint32_t> begins;  // per border subtree, in key order
};

// The sweep's output, before lay_out_lbvh gathers it into a Bvh.
struct LbvhSweep {
  uint32_t key_count = 0;
  uint32_t chunk_keys = 0;
  // Pairs of flat nodes (interior nodes' `first` still an id), every chunk's in one block, the
  // blocks in the order the chunks finished; the border pass's pairs are in top_pairs, their ids
  // from 2 key_count on.
  ParallelArray<BvhNode> pairs;
  std::vector<LbvhChunk> chunks;
  std::vector<BvhNode> top_pairs;
  uint32_t top_pair_count = 0;  // pair k of the border pass at top_pairs[top_pairs.size() - 2 (k + 1)]
  LbvhSubtree root;
  uint32_t height = 0;  // levels of the flat tree (root.height); 0 without keys
};

// The sweep over order.codes (key i is primitive order.prims[i], box input.boxes[order.prims[i]]),
// with collapse costs from `options`, in chunks of lbvh_chunk_keys(keys) keys, or of chunk_keys where
// given (tests use other sizes; glint::Error for 0).
LbvhSweep sweep_lbvh(const BuildInput& input, const MortonOrder& order, const BuildOptions& options);
LbvhSweep sweep_lbvh(const BuildInput& input, const MortonOrder& order, const BuildOptions& options,
                     uint32_t chunk_keys);

// The flat Bvh of a sweep: the root at node 0, then every pair depth first (a node's pair, then
// one child's descendants, then the other's: left first where the border pass made the node, right
// first where a chunk did). prim_indices = `prims` (the Morton order: a leaf over keys [first,
// last] is exactly those).
// glint::Error when the tree is deeper than kMaxBvhDepth (build_lbvh then takes the path that can
// rebalance).
Bvh lay_out_lbvh(const LbvhSweep& sweep, UnzeroedVector<uint32_t> prims, const std::string& builder);

}  // namespace glint::accel::detail
