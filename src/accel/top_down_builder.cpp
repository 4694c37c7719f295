#include "accel/top_down_builder.h"

#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_group.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <numeric>
#include <vector>

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

struct Builder {
  const BuildInput& input;
  const BuildOptions& options;
  SplitPolicy policy;
  std::vector<BvhNode>& nodes;
  std::vector<uint32_t>& prim_indices;
  std::atomic<uint32_t> next_node{1};
  std::atomic<uint32_t> depth{0};

  void build(uint32_t node_index, const PrimRange& range, uint32_t level) {
    BvhNode& node = nodes[node_index];
    node.set_bounds(range.box);
    uint32_t seen = depth.load(std::memory_order_relaxed);
    while (level > seen && !depth.compare_exchange_weak(seen, level, std::memory_order_relaxed)) {
    }

    const uint32_t count = range.size();
    const bool parallel = count >= options.parallel_threshold;
    const SplitContext context{input, options, prim_indices, parallel};
    std::optional<uint32_t> mid;
    if (count > 1) mid = policy(context, range);
    if (!mid && count <= options.max_leaf_size) {
      node.first = range.begin;
      node.prim_count = count;
      return;
    }
    const auto fits_depth = [&](uint32_t child_count) {
      return level + 1 + median_levels(child_count, options.max_leaf_size) <= kMaxBvhDepth;
    };
    if (!mid || !fits_depth(*mid - range.begin) || !fits_depth(range.end - *mid))
      mid = object_median_split(context, range);

    const uint32_t left = next_node.fetch_add(2, std::memory_order_relaxed);
    node.first = left;
    node.prim_count = 0;
    const auto build_child = [this, level, parallel](uint32_t child, uint32_t begin, uint32_t end) {
      build(child, bound_range(input, prim_indices, begin, end, parallel), level + 1);
    };
    if (parallel) {
      tbb::task_group group;
      group.run([&] { build_child(left, range.begin, *mid); });
      build_child(left + 1, *mid, range.end);
      group.wait();
    } else {
      build_child(left, range.begin, *mid);
      build_child(left + 1, *mid, range.end);
    }
  }
};

// Node indices handed out by concurrent tasks depend on scheduling; renumber depth-first so the
// same input always gives the same array (reproducible stats, diffs and GPU uploads).
std::vector<BvhNode> depth_first_order(const std::vector<BvhNode>& nodes) {
  std::vector<BvhNode> ordered;
  ordered.reserve(nodes.size());
  ordered.push_back(nodes[0]);
  std::vector<uint32_t> stack{0};
  while (!stack.empty()) {
    const uint32_t index = stack.back();
    stack.pop_back();
    if (ordered[index].is_leaf()) continue;
    const uint32_t old_left = ordered[index].left();
    const auto new_left = static_cast<uint32_t>(ordered.size());
    ordered.push_back(nodes[old_left]);
    ordered.push_back(nodes[old_left + 1]);
    ordered[index].first = new_left;
    stack.push_back(new_left + 1);
    stack.push_back(new_left);
  }
  return ordered;
}

}  // namespace

PrimRange bound_range(const BuildInput& input, std::span<const uint32_t> prim_indices, uint32_t begin, uint32_t end,
                      bool parallel) {
  PrimRange range{begin, end, {}, {}};
  const auto accumulate = [&](uint32_t from, uint32_t to, PrimRange acc) {
    for (uint32_t i = from; i != to; ++i) {
      const uint32_t prim = prim_indices[i];
      acc.box.extend(input.boxes[prim]);
      acc.centroid_box.extend(input.centroids[prim]);
    }
    return acc;
  };
  if (!parallel) return accumulate(begin, end, range);
  return tbb::parallel_reduce(
      tbb::blocked_range<uint32_t>(begin, end, 1024), range,
      [&](const tbb::blocked_range<uint32_t>& r, PrimRange acc) { return accumulate(r.begin(), r.end(), acc); },
      [](PrimRange a, const PrimRange& b) {
        a.box.extend(b.box);
        a.centroid_box.extend(b.centroid_box);
        return a;
      });
}

uint32_t object_median_split(const SplitContext& context, const PrimRange& range) {
  const uint32_t mid = range.begin + range.size() / 2;
  const vec3 extent = range.centroid_box.extent();
  if (extent.x <= 0.0f && extent.y <= 0.0f && extent.z <= 0.0f) return mid;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  const auto& centroids = context.input.centroids;
  const auto first = context.prim_indices.begin();
  std::nth_element(first + range.begin, first + mid, first + range.end, [&](uint32_t a, uint32_t b) {
    // Ties broken by index so the result does not depend on the incoming order's history.
    return centroids[a][axis] < centroids[b][axis] || (centroids[a][axis] == centroids[b][axis] && a < b);
  });
  return mid;
}

Bvh build_top_down(const BuildInput& input, const BuildOptions& options, const std::string& name, SplitPolicy policy) {
  const auto start = std::chrono::steady_clock::now();
  if (input.boxes.size() != input.centroids.size())
    fail("accel: build_{}: {} boxes but {} centroids", name, input.boxes.size(), input.centroids.size());
  if (input.boxes.size() >= (size_t{1} << 31))
    fail("accel: build_{}: {} primitives, at most 2^31 - 1", name, input.boxes.size());
  if (options.max_leaf_size < 1) fail("accel: build_{}: max_leaf_size must be at least 1", name);

  Bvh bvh;
  bvh.builder = name;
  const auto count = static_cast<uint32_t>(input.boxes.size());
  bvh.prim_indices.resize(count);
  std::iota(bvh.prim_indices.begin(), bvh.prim_indices.end(), 0u);
  if (count > 0) {
    // A binary tree over n leaves-worth of primitives has at most 2n - 1 nodes.
    std::vector<BvhNode> nodes(2 * size_t{count} - 1);
    Builder builder{input, options, policy, nodes, bvh.prim_indices};
    const PrimRange root = bound_range(input, bvh.prim_indices, 0, count, count >= options.parallel_threshold);
    builder.build(0, root, 1);
    nodes.resize(builder.next_node.load());
    bvh.nodes = depth_first_order(nodes);
    bvh.depth = builder.depth.load();
  }
  bvh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return bvh;
}

}  // namespace glint::accel::detail
