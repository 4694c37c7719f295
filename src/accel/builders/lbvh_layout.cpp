#include "accel/builders/lbvh_layout.h"

#include "accel/builders/radix_tree_sweep.h"
#include "accel/unzeroed_vector.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <span>

namespace glint::accel::detail {
namespace {

// Writes the flat node of a finished subtree: a leaf over its keys, or an interior node whose
// `first` is its children's pair (in the sweep's numbering until lay_out_lbvh rebases it). Field by
// field into place: a BvhNode assembled on the stack and copied whole stalled on store forwarding.
void write_flat_node(const LbvhSubtree& subtree, BvhNode& node) {
  node.set_bounds(subtree.box);
  if (subtree.collapse) {
    node.first = subtree.first;
    node.prim_count = subtree.last - subtree.first + 1;
  } else {
    node.first = subtree.children;
    node.prim_count = 0;
  }
}

BvhNode flat_node(const LbvhSubtree& subtree) {
  BvhNode node;
  write_flat_node(subtree, node);
  return node;
}

// Sibling pairs written downwards from `end` of `storage`: pair k at end - 2 (k + 1), known to the
// rest of the sweep as that position plus id_base.
struct PairOutput {
  BvhNode* storage;
  uint32_t end;
  uint32_t id_base;
  uint32_t count = 0;

  uint32_t write(const LbvhSubtree& left, const LbvhSubtree& right) {
    const uint32_t at = end - 2 * ++count;
    write_flat_node(left, storage[at]);
    write_flat_node(right, storage[at + 1]);
    return id_base + at;
  }
};

// The stack machine of lbvh_layout.h over finished subtrees given in key order.
class SubtreeStack {
 public:
  // `blocked` receives the right children whose sibling lies before the first subtree given (the
  // chunk's start); null where there is none (the border pass starts at key 0).
  SubtreeStack(std::span<const uint64_t> codes, const BuildOptions& options, PairOutput& output,
               std::vector<LbvhSubtree>* blocked)
      : delta_{codes}, last_key_(static_cast<uint32_t>(codes.size()) - 1), options_(options), output_(output),
        blocked_(blocked) {
    stack_.reserve(128);  // more than the deepest radix tree of 64 + 32 bit keys
  }

  // Makes `subtree` key `key`, with its box, as the next subtree to add.
  void make_leaf(uint32_t key, const Aabb& box, LbvhSubtree& subtree) const {
    subtree.box = box;
    subtree.cost = leaf_cost(box, options_);
    subtree.first = subtree.last = key;
    subtree.pairs_begin = output_.count;
    subtree.height = 1;
    subtree.collapse = true;
  }

  // Merges `subtree`, the next one in key order, up as far as the subtrees given so far allow
  // (`subtree` is left as whatever it became).
  void add(LbvhSubtree& subtree) {
    while (subtree.first != 0 || subtree.last != last_key_) {
      const bool is_left_child =
          subtree.first == 0 ||
          (subtree.last != last_key_ && delta_(subtree.last, subtree.last + 1) > delta_(subtree.first - 1, subtree.first));
      if (is_left_child) break;
      // A right child: its sibling ends just before it, and if it was finished here it is the top
      // of the stack (everything pushed after it lies inside this subtree and was merged).
      if (stack_.empty()) {
        if (blocked_ == nullptr) fail("accel: build_lbvh: the radix tree sweep lost the sibling of keys {}-{}", subtree.first, subtree.last);
        blocked_->push_back(subtree);
        return;
      }
      merge_into_right(stack_.back(), subtree);
      stack_.pop_back();
    }
    stack_.push_back(subtree);  // a left child waiting for its sibling, or the root
  }

  std::vector<LbvhSubtree>& stack() { return stack_; }

 private:
  // Makes `right` its parent with `left`, in place (the subtrees are plain data on the stack, and
  // copying them whole, or a SubtreeSummary returned by value, stalled on store forwarding).
  void merge_into_right(const LbvhSubtree& left, LbvhSubtree& right) {
    Aabb box = left.box;
    box.extend(right.box);
    const CollapseChoice choice =
        choose_collapse(half_area(box), right.last - left.first + 1, left.cost, right.cost, options_);
    if (choice.collapse)
      output_.count = left.pairs_begin;  // the subtree's pairs are the last ones written: drop them
    else
      right.children = output_.write(left, right);
    right.height = choice.collapse ? 1 : 1 + std::max(left.height, right.height);
    right.collapse = choice.collapse;
    right.cost = choice.cost;
    right.box = box;
    right.first = left.first;
    right.pairs_begin = left.pairs_begin;
  }

  CommonPrefix delta_;
  uint32_t last_key_;
  const BuildOptions& options_;
  PairOutput& output_;
  std::vector<LbvhSubtree>* blocked_;
  std::vector<LbvhSubtree> stack_;
};

// Chunk c's subtrees left for the border pass, in key order, after sweeping its keys. Its pairs are
// written into `local` (one per thread, twice the chunk's keys: as many as it could need, and small
// enough to stay in cache), then copied to the next free place in sweep.pairs: the shared array is
// then filled from the start, and its pages past what the pairs need are never touched.
std::vector<LbvhSubtree> sweep_chunk(const BuildInput& input, const MortonOrder& order, const BuildOptions& options,
                                     uint32_t c, UnzeroedVector<BvhNode>& local, std::atomic<uint32_t>& stored,
                                     LbvhSweep& sweep) {
  const uint32_t begin = c * sweep.chunk_keys;
  const uint32_t end = std::min(sweep.key_count, begin + sweep.chunk_keys);
  local.resize(2 * size_t{sweep.chunk_keys});  // only the pairs written are read (unzeroed_vector.h)
  const uint32_t local_end = 2 * (end - begin);
  PairOutput output{local.data(), local_end, 2 * begin};  // ids as if the region were [2 begin, 2 end)
  std::vector<LbvhSubtree> border;
  SubtreeStack stack(order.codes, options, output, &border);
  LbvhSubtree subtree;
  for (uint32_t key = begin; key != end; ++key) {
    prefetch_box_ahead(input, order.prims, key);
    stack.make_leaf(key, input.boxes[order.prims[key]], subtree);
    stack.add(subtree);
  }
  // The blocked right children come first in key order, then the left children still waiting.
  border.insert(border.end(), stack.stack().begin(), stack.stack().end());
  LbvhChunk& chunk = sweep.chunks[c];
  chunk.region_end = 2 * end;
  chunk.pair_count = output.count;
  chunk.stored_at = stored.fetch_add(2 * output.count, std::memory_order_relaxed);
  std::copy(local.begin() + (local_end - 2 * output.count), local.begin() + local_end, sweep.pairs.begin() + chunk.stored_at);
  chunk.begins.resize(border.size());
  for (size_t i = 0; i < border.size(); ++i) chunk.begins[i] = border[i].pairs_begin;
  return border;
}

// The pair after run i of `chunk` (LbvhChunk::begins).
uint32_t run_end(const LbvhChunk& chunk, size_t i) {
  return i + 1 < chunk.begins.size() ? chunk.begins[i + 1] : chunk.pair_count;
}

// Which of chunk `chunk`'s runs (LbvhChunk::begins) holds the pair at sweep position `id`.
size_t run_of(const LbvhChunk& chunk, uint32_t id) {
  const uint32_t pair = (chunk.region_end - id) / 2 - 1;
  return static_cast<size_t>(std::upper_bound(chunk.begins.begin(), chunk.begins.end(), pair) - chunk.begins.begin()) - 1;
}

}  // namespace

uint32_t lbvh_chunk_keys(uint32_t key_count) {
  constexpr uint32_t kMinChunkKeys = 1024, kMaxChunkKeys = 8192, kChunks = 64;
  return std::clamp(std::bit_ceil(key_count / kChunks), kMinChunkKeys, kMaxChunkKeys);
}

LbvhSweep sweep_lbvh(const BuildInput& input, const MortonOrder& order, const BuildOptions& options) {
  return sweep_lbvh(input, order, options, lbvh_chunk_keys(static_cast<uint32_t>(order.prims.size())));
}

LbvhSweep sweep_lbvh(const BuildInput& input, const MortonOrder& order, const BuildOptions& options,
                     uint32_t chunk_keys) {
  if (chunk_keys == 0) fail("accel: build_lbvh: chunks of 0 keys");
  LbvhSweep sweep;
  sweep.key_count = static_cast<uint32_t>(order.prims.size());
  sweep.chunk_keys = chunk_keys;
  if (sweep.key_count == 0) return sweep;
  const uint32_t chunk_count = (sweep.key_count - 1) / chunk_keys + 1;
  sweep.pairs = ParallelArray<BvhNode>(2 * size_t{sweep.key_count}, kForOverwrite);  // written before read
  sweep.chunks.resize(chunk_count);
  std::vector<std::vector<LbvhSubtree>> borders(chunk_count);
  tbb::enumerable_thread_specific<UnzeroedVector<BvhNode>> local_pairs;
  std::atomic<uint32_t> stored{0};
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, chunk_count, 1), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t c = r.begin(); c != r.end(); ++c)
      borders[c] = sweep_chunk(input, order, options, c, local_pairs.local(), stored, sweep);
  });

  // The border pass: every chunk's leftovers, in key order, through the same machine.
  size_t border_count = 0;
  for (const auto& border : borders) border_count += border.size();
  sweep.top_pairs.resize(2 * border_count);
  PairOutput output{sweep.top_pairs.data(), static_cast<uint32_t>(sweep.top_pairs.size()), 2 * sweep.key_count};
  SubtreeStack stack(order.codes, options, output, nullptr);
  for (auto& border : borders)
    for (LbvhSubtree& subtree : border) {
      subtree.pairs_begin = output.count;  // its own pairs stay in its chunk
      stack.add(subtree);
    }
  if (stack.stack().size() != 1) fail("accel: build_lbvh: the radix tree sweep ended with {} roots", stack.stack().size());
  sweep.top_pair_count = output.count;
  sweep.root = stack.stack().front();
  sweep.height = sweep.root.height;
  return sweep;
}

Bvh lay_out_lbvh(const LbvhSweep& sweep, UnzeroedVector<uint32_t> prims, const std::string& builder) {
  Bvh bvh;
  bvh.builder = builder;
  if (sweep.key_count == 0) return bvh;
  if (sweep.height > kMaxBvhDepth)
    fail("accel: build_{}: the radix tree is {} levels deep, more than {}", builder, sweep.height, kMaxBvhDepth);
  const uint32_t top_base = 2 * sweep.key_count;  // sweep ids from here on are the border pass's

  // The final order is depth-first, so that every subtree's descendants are one contiguous range
  // (refit.cpp cuts the tree into such ranges): a walk of the border pass's tree places each of its
  // pairs, then the left child's descendants, then the right child's; where it reaches a subtree a
  // chunk made, that subtree's run of pairs goes, already in depth-first order (the right child's
  // descendants first). A chunk's run is left out when a leaf of the border pass collapsed over it.
  struct Run {
    bool kept = false;
    int64_t shift = 0;  // final index - id
  };
  std::vector<std::vector<Run>> runs(sweep.chunks.size());
  for (size_t c = 0; c < sweep.chunks.size(); ++c) runs[c].resize(sweep.chunks[c].begins.size());
  const auto run_at = [&](uint32_t id) -> Run& {
    const size_t c = id / (2 * sweep.chunk_keys);
    return runs[c][run_of(sweep.chunks[c], id)];
  };
  const auto top_pair = [&](uint32_t id) { return (static_cast<uint32_t>(sweep.top_pairs.size()) - (id - top_base)) / 2 - 1; };
  std::vector<uint32_t> top_at(sweep.top_pair_count);  // final index of the border pass's pair k
  const BvhNode root = flat_node(sweep.root);
  uint32_t next = 1;
  std::vector<BvhNode> walk{root};
  while (!walk.empty()) {
    const BvhNode node = walk.back();
    walk.pop_back();
    if (node.is_leaf()) continue;
    if (node.first >= top_base) {
      top_at[top_pair(node.first)] = next;
      next += 2;
      const BvhNode* pair = &sweep.top_pairs[node.first - top_base];
      walk.push_back(pair[1]);
      walk.push_back(pair[0]);
      continue;
    }
    const size_t c = node.first / (2 * sweep.chunk_keys);
    const LbvhChunk& chunk = sweep.chunks[c];
    const size_t i = run_of(chunk, node.first);
    const uint32_t end = run_end(chunk, i);
    Run& run = runs[c][i];
    run.kept = true;
    run.shift = int64_t{next} - (int64_t{chunk.region_end} - 2 * int64_t{end});
    next += 2 * (end - chunk.begins[i]);
  }

  bvh.nodes.resize(next);  // every node written below (unzeroed_vector.h)
  tbb::parallel_for(tbb::blocked_range<size_t>(0, sweep.chunks.size(), 1), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t c = r.begin(); c != r.end(); ++c) {
      const LbvhChunk& chunk = sweep.chunks[c];
      for (size_t i = 0; i < chunk.begins.size(); ++i) {
        if (!runs[c][i].kept) continue;
        const uint32_t end = run_end(chunk, i);
        const uint32_t from = chunk.region_end - 2 * end, to = chunk.region_end - 2 * chunk.begins[i];
        const int64_t shift = runs[c][i].shift;
        // A run's interior nodes link only to pairs of the same run.
        const BvhNode* stored = &sweep.pairs[chunk.stored_at] - (chunk.region_end - 2 * chunk.pair_count);
        for (uint32_t id = from; id != to; ++id) {
          BvhNode node = stored[id];
          if (!node.is_leaf()) node.first = static_cast<uint32_t>(node.first + shift);
          bvh.nodes[static_cast<uint32_t>(id + shift)] = node;
        }
      }
    }
  });
  const auto rebased = [&](BvhNode node) {
    if (node.is_leaf()) return node;
    node.first = node.first >= top_base ? top_at[top_pair(node.first)]
                                        : static_cast<uint32_t>(node.first + run_at(node.first).shift);
    return node;
  };
  bvh.nodes[0] = rebased(root);
  for (uint32_t k = 0; k < sweep.top_pair_count; ++k) {
    const BvhNode* pair = &sweep.top_pairs[sweep.top_pairs.size() - 2 * (k + 1)];
    bvh.nodes[top_at[k]] = rebased(pair[0]);
    bvh.nodes[top_at[k] + 1] = rebased(pair[1]);
  }
  bvh.prim_indices = std::move(prims);
  bvh.depth = sweep.height;
  return bvh;
}

}  // namespace glint::accel::detail
