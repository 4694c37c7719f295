#include "accel/builders/top_down_builder.h"

#include "accel/builders/parallel_array.h"
#include "core/error.h"

#include <tbb/task_group.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <type_traits>

namespace glint::accel::detail {
namespace {

// Levels an object-median build still needs below a node of `count` primitives (0 for a leaf).
// Each median split halves the larger child, so this drops by exactly one per level: checking it at
// every split keeps the whole tree within kMaxBvhDepth whatever the policy does.
uint32_t median_levels(uint32_t count, uint32_t max_leaf_size) {
  uint32_t levels = 0;
  while (count > max_leaf_size) {
    count = count - count / 2;
    ++levels;
  }
  return levels;
}

// A node as the recursion leaves it. Tasks take sibling pairs (or, for a subtree built by one thread,
// a block of slots) from a shared counter, so indices depend on scheduling until renumber() lays the
// tree out depth-first.
struct BuildNode {
  vec3 bounds_min;
  uint32_t first;  // left child (interior) or first prim_indices slot (leaf)
  vec3 bounds_max;
  uint32_t prim_count;   // 0 for an interior node
  uint32_t descendants;  // nodes below this one
};

// Allocated uninitialised (2n - 1 of them, most never touched): no thread zeroes 40 MB up front.
static_assert(std::is_trivially_copyable_v<BuildNode> && std::is_trivially_destructible_v<BuildNode>);

struct Builder {
  const BuildOptions& options;
  SplitPolicy policy;
  uint32_t chunk;
  BuildNode* nodes;
  std::array<std::span<PrimRef>, 2> refs;  // a range's references are in one, the other is scratch
  std::span<uint32_t> prim_indices;
  // Node slots are handed out from here to nodes split in parallel and, in bulk, to subtrees one
  // thread builds alone. On its own cache line: the fields above are read at every node by every
  // thread, and an atomic updated next to them made each update invalidate them on all the others.
  alignas(64) std::atomic<uint32_t> next_node{1};

  SplitContext context(int buffer, bool parallel) const {
    return {options, refs[static_cast<size_t>(buffer)], refs[static_cast<size_t>(1 - buffer)], parallel, chunk};
  }

  void make_leaf(BuildNode& node, const PrimRange& range, int buffer) {
    node.first = range.begin;
    node.prim_count = range.size();
    node.descendants = 0;
    const std::span<const PrimRef> from = refs[static_cast<size_t>(buffer)];
    for (uint32_t i = range.begin; i != range.end; ++i) prim_indices[i] = from[i].prim;
  }

  // Builds the subtree over `range`, whose references are in refs[buffer], at nodes[index]; returns
  // its height. serial_next: inside a subtree that this thread builds alone, its next free slot.
  uint32_t build(uint32_t index, const PrimRange& range, int buffer, uint32_t level, uint32_t* serial_next) {
    BuildNode& node = nodes[index];
    node.bounds_min = range.box.min;
    node.bounds_max = range.box.max;
    const uint32_t count = range.size();
    const bool parallel = count >= options.parallel_threshold;
    std::optional<Split> split;
    if (count > 1) split = policy(context(buffer, parallel), range);
    if (!split && count <= options.max_leaf_size) {
      make_leaf(node, range, buffer);
      return 1;
    }
    if (split && split->moved) buffer = 1 - buffer;
    const auto fits_depth = [&](const PrimRange& child) {
      return child.size() > 0 && level + 1 + median_levels(child.size(), options.max_leaf_size) <= kMaxBvhDepth;
    };
    if (!split || !fits_depth(split->left) || !fits_depth(split->right))
      split = object_median_split(context(buffer, parallel), range);

    // A subtree that one thread builds takes its slots from one reservation: one atomic per subtree
    // instead of one per node, and its nodes are contiguous, so threads do not write to the same
    // cache lines. Below its root a binary tree over `count` primitives has at most 2 count - 2
    // nodes; the reservations and the nodes split in parallel (a binary tree whose leaves are the
    // reserving subtrees) then never take more than the 2 n - 1 slots there are.
    uint32_t left = 0, reserved_next = 0;
    if (parallel) {
      left = next_node.fetch_add(2, std::memory_order_relaxed);
    } else if (serial_next == nullptr) {
      left = next_node.fetch_add(2 * count - 2, std::memory_order_relaxed);
      reserved_next = left + 2;
      serial_next = &reserved_next;
    } else {
      left = *serial_next;
      *serial_next += 2;
    }
    node.first = left;
    node.prim_count = 0;
    uint32_t left_height = 0, right_height = 0;
    if (parallel) {
      tbb::task_group group;
      group.run([&] { left_height = build(left, split->left, buffer, level + 1, nullptr); });
      right_height = build(left + 1, split->right, buffer, level + 1, nullptr);
      group.wait();
    } else {
      left_height = build(left, split->left, buffer, level + 1, serial_next);
      right_height = build(left + 1, split->right, buffer, level + 1, serial_next);
    }
    node.descendants = 2 + nodes[left].descendants + nodes[left + 1].descendants;
    return 1 + std::max(left_height, right_height);
  }
};

// Writes the tree depth-first into `to` so the same input always gives the same array (reproducible
// stats, diffs and GPU uploads): a node's two children first, then the left child's descendants, then
// the right child's. Every subtree's place follows from the descendant counts, so large subtrees are
// written by parallel tasks.
struct Renumberer {
  const BuildNode* from;
  BvhNode* to;
  uint32_t parallel_threshold;

  void emit(uint32_t old_index, uint32_t index, uint32_t descendants_at) const {
    const BuildNode& node = from[old_index];
    BvhNode& out = to[index];
    out.bounds_min = node.bounds_min;
    out.bounds_max = node.bounds_max;
    out.prim_count = node.prim_count;
    if (node.prim_count != 0) {
      out.first = node.first;
      return;
    }
    out.first = descendants_at;
    const uint32_t left = node.first;
    const uint32_t right_descendants_at = descendants_at + 2 + from[left].descendants;
    if (node.descendants >= parallel_threshold) {
      tbb::task_group group;
      group.run([&] { emit(left, descendants_at, descendants_at + 2); });
      emit(left + 1, descendants_at + 1, right_descendants_at);
      group.wait();
    } else {
      emit(left, descendants_at, descendants_at + 2);
      emit(left + 1, descendants_at + 1, right_descendants_at);
    }
  }
};

}  // namespace

uint32_t parallel_chunk(const BuildOptions& options) { return std::clamp(options.parallel_threshold, 32u, 8192u); }

Split object_median_split(const SplitContext& context, const PrimRange& range) {
  const uint32_t mid = range.begin + range.size() / 2;
  const vec3 extent = range.centroid_box.extent();
  if (extent.x > 0.0f || extent.y > 0.0f || extent.z > 0.0f) {
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto first = context.refs.begin();
    std::nth_element(first + range.begin, first + mid, first + range.end, [axis](const PrimRef& a, const PrimRef& b) {
      return a.centroid[axis] < b.centroid[axis] || (a.centroid[axis] == b.centroid[axis] && a.prim < b.prim);
    });
  }
  return {bound_refs(context.refs, range.begin, mid, context.parallel, context.chunk),
          bound_refs(context.refs, mid, range.end, context.parallel, context.chunk), false};
}

Bvh build_top_down(const BuildInput& input, const BuildOptions& options, const std::string& name, SplitPolicy policy) {
  if (input.boxes.size() != input.centroids.size())
    fail("accel: build_{}: {} boxes but {} centroids", name, input.boxes.size(), input.centroids.size());
  if (input.boxes.size() >= (size_t{1} << 31))
    fail("accel: build_{}: {} primitives, at most 2^31 - 1", name, input.boxes.size());
  if (options.max_leaf_size < 1) fail("accel: build_{}: max_leaf_size must be at least 1", name);

  Bvh bvh;
  bvh.builder = name;
  const auto count = static_cast<uint32_t>(input.boxes.size());
  if (count > 0) {
    const uint32_t chunk = parallel_chunk(options);
    ParallelArray<PrimRef> refs(count, kForOverwrite);
    ParallelArray<PrimRef> scratch(count, kForOverwrite);
    // A binary tree over n leaves-worth of primitives has at most 2n - 1 nodes.
    ParallelArray<BuildNode> nodes(2 * size_t{count} - 1, kForOverwrite);
    bvh.prim_indices.resize(count);
    Builder builder{options, policy, chunk, nodes.data(), {std::span<PrimRef>(refs), std::span<PrimRef>(scratch)},
                    bvh.prim_indices};
    const PrimRange root = make_prim_refs(input, builder.refs[0], chunk);
    bvh.depth = builder.build(0, root, 0, 1, nullptr);
    // Reserved slots that subtrees did not use leave gaps in `nodes`; the renumbering follows child
    // links, so only the count of real nodes matters here.
    bvh.nodes.resize(1 + nodes[0].descendants);
    const Renumberer renumberer{nodes.data(), bvh.nodes.data(), std::max(options.parallel_threshold, 2u)};
    renumberer.emit(0, 0, 1);
  }
  return bvh;
}

}  // namespace glint::accel::detail
