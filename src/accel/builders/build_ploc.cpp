#include "accel/builders/build_ploc.h"

#include "accel/builders/binary_tree.h"
#include "accel/builders/bvh_collapse_leaves.h"
#include "accel/builders/morton.h"
#include "core/error.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_scan.h>

#include <algorithm>

namespace glint::accel {
namespace {

using detail::BinaryTree;
using detail::kNoNode;

// The clusters of one iteration, in Morton order: tree node and its box (kept here as well so the
// neighbour search reads consecutive memory).
struct Clusters {
  std::vector<uint32_t> nodes;
  std::vector<Aabb> boxes;

  uint32_t size() const { return static_cast<uint32_t>(nodes.size()); }
};

// Among pairs at equal distance prefer neighbours (smaller gap), then pairs starting at an even
// position, then the earlier pair. The parity term matters for runs of identical boxes: it pairs
// (0, 1), (2, 3), ... so such a run halves in every iteration instead of losing one cluster.
uint64_t tie_key(uint32_t i, uint32_t j) {
  const uint32_t first = std::min(i, j), gap = std::max(i, j) - first;
  return (uint64_t{gap} << 33) | (uint64_t{first & 1u} << 32) | first;
}

// Nearest neighbour of every cluster within `radius` positions. Distances are symmetric, and ties
// are broken by a key of the pair alone (tie_key), so all candidate pairs are strictly ordered by
// (distance, key): the globally least pair is then mutual and every iteration merges at least one.
// Because that order is strict, the result does not depend on the order of evaluation, which lets
// each chunk of positions evaluate every pair once and offer it to both ends.
void find_nearest_neighbours(const Clusters& clusters, uint32_t radius, std::vector<uint32_t>& nearest) {
  const uint32_t count = clusters.size();
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, 1024), [&](const tbb::blocked_range<uint32_t>& r) {
    const uint32_t begin = r.begin(), end = r.end();
    std::vector<uint32_t> best(end - begin, kNoNode);
    std::vector<float> best_distance(end - begin, 0.0f);
    const auto offer = [&](uint32_t i, uint32_t j, float distance) {
      const uint32_t slot = i - begin;
      if (best[slot] == kNoNode || distance < best_distance[slot] ||
          (distance == best_distance[slot] && tie_key(i, j) < tie_key(i, best[slot]))) {
        best[slot] = j;
        best_distance[slot] = distance;
      }
    };
    // Pairs (i, j) with i < j <= i + radius and at least one end in [begin, end).
    for (uint32_t i = begin > radius ? begin - radius : 0; i < end; ++i) {
      const uint32_t last = count - 1 - i > radius ? i + radius : count - 1;
      for (uint32_t j = std::max(i + 1, begin); j <= last; ++j) {
        Aabb merged = clusters.boxes[i];
        merged.extend(clusters.boxes[j]);
        const float distance = half_area(merged);
        if (i >= begin) offer(i, j, distance);
        if (j < end) offer(j, i, distance);
      }
    }
    std::copy(best.begin(), best.end(), nearest.begin() + begin);
  });
}

// Per position: 1 when it starts a merge (mutual neighbours, lower position of the pair), and 1
// when it survives compaction (not the higher position of a mutual pair).
struct ScanCounts {
  uint32_t merges = 0;
  uint32_t survivors = 0;
};

void merge_and_compact(BinaryTree& tree, Clusters& clusters, const std::vector<uint32_t>& nearest,
                       uint32_t& next_node, Clusters& next) {
  const uint32_t count = clusters.size();
  const auto merges_here = [&](uint32_t i) { return nearest[nearest[i]] == i && i < nearest[i]; };
  const auto survives = [&](uint32_t i) { return nearest[nearest[i]] != i || i < nearest[i]; };

  // Exclusive prefix sums: the new tree node of each merge and the new position of each survivor.
  std::vector<ScanCounts> offsets(count);
  const ScanCounts totals = tbb::parallel_scan(
      tbb::blocked_range<uint32_t>(0, count, 4096), ScanCounts{},
      [&](const tbb::blocked_range<uint32_t>& r, ScanCounts running, bool is_final) {
        for (uint32_t i = r.begin(); i != r.end(); ++i) {
          if (is_final) offsets[i] = running;
          running.merges += merges_here(i) ? 1u : 0u;
          running.survivors += survives(i) ? 1u : 0u;
        }
        return running;
      },
      [](const ScanCounts& a, const ScanCounts& b) { return ScanCounts{a.merges + b.merges, a.survivors + b.survivors}; });

  next.nodes.resize(totals.survivors);
  next.boxes.resize(totals.survivors);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, 4096), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t i = r.begin(); i != r.end(); ++i) {
      if (!survives(i)) continue;
      const uint32_t slot = offsets[i].survivors;
      if (!merges_here(i)) {
        next.nodes[slot] = clusters.nodes[i];
        next.boxes[slot] = clusters.boxes[i];
        continue;
      }
      const uint32_t j = nearest[i];
      const uint32_t node = next_node + offsets[i].merges;
      Aabb box = clusters.boxes[i];
      box.extend(clusters.boxes[j]);
      detail::TreeNode& merged = tree.nodes[node];
      merged.left = clusters.nodes[i];
      merged.right = clusters.nodes[j];
      merged.box = box;
      tree.nodes[merged.left].parent = node;
      tree.nodes[merged.right].parent = node;
      next.nodes[slot] = node;
      next.boxes[slot] = box;
    }
  });
  next_node += totals.merges;
  std::swap(clusters, next);
}

BinaryTree build_ploc_tree(const BuildInput& input, uint32_t radius) {
  const MortonOrder order = sort_by_morton(input.centroids);
  BinaryTree tree = detail::make_leaves(input, order.prims);
  const uint32_t count = tree.leaf_count;
  if (count < 2) return tree;

  Clusters clusters;
  clusters.nodes.resize(count);
  clusters.boxes.resize(count);
  tbb::parallel_for(tbb::blocked_range<uint32_t>(0, count, 8192), [&](const tbb::blocked_range<uint32_t>& r) {
    for (uint32_t i = r.begin(); i != r.end(); ++i) {
      clusters.nodes[i] = i;
      clusters.boxes[i] = tree.nodes[i].box;
    }
  });
  Clusters next;
  std::vector<uint32_t> nearest(count);
  uint32_t next_node = count;
  while (clusters.size() > 1) {
    find_nearest_neighbours(clusters, radius, nearest);
    merge_and_compact(tree, clusters, nearest, next_node, next);
  }
  tree.root = clusters.nodes[0];
  return tree;
}

}  // namespace

Bvh build_ploc(const BuildInput& input, const BuildOptions& options) {
  detail::check_build_input(input, options, "ploc");
  if (options.ploc_radius < 1) fail("accel: build_ploc: ploc_radius must be at least 1, got {}", options.ploc_radius);
  BinaryTree tree = build_ploc_tree(input, options.ploc_radius);
  Bvh bvh = detail::flatten_tree(tree, options, "ploc");
  return bvh;
}

}  // namespace glint::accel
