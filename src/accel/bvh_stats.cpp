#include "accel/bvh_stats.h"

#include "accel/builders/primitive_bounds.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>
#include <vector>

namespace glint::accel {

double sah_cost(const Bvh& bvh, const BuildOptions& build) {
  return compute_stats(bvh, sah_costs(build)).sah_cost;
}

BvhStats compute_stats(const Bvh& bvh, const SahCosts& costs) {
  BvhStats stats;
  stats.nodes = bvh.nodes.size();
  stats.primitives = bvh.prim_indices.size();
  stats.memory_bytes = bvh.nodes.size() * sizeof(BvhNode) + bvh.prim_indices.size() * sizeof(uint32_t);
  stats.build_ms = bvh.build_ms;
  if (bvh.nodes.empty()) return stats;

  double interior_area = 0.0;
  double leaf_area_times_prims = 0.0;
  size_t leaf_prims = 0;
  std::vector<std::pair<uint32_t, uint32_t>> stack{{0u, 1u}};  // node, depth
  while (!stack.empty()) {
    const auto [index, depth] = stack.back();
    stack.pop_back();
    const BvhNode& node = bvh.nodes[index];
    stats.max_depth = std::max(stats.max_depth, depth);
    const double area = half_area(node.bounds());
    if (node.is_leaf()) {
      ++stats.leaves;
      leaf_prims += node.prim_count;
      stats.max_leaf_size = std::max(stats.max_leaf_size, node.prim_count);
      leaf_area_times_prims += area * node.prim_count;
    } else {
      ++stats.interior_nodes;
      interior_area += area;
      stack.push_back({node.left(), depth + 1});
      stack.push_back({node.right(), depth + 1});
    }
  }
  stats.mean_leaf_size = static_cast<double>(leaf_prims) / static_cast<double>(stats.leaves);
  const double root_area = half_area(bvh.nodes[0].bounds());
  // A flat scene (zero-area root) has no meaningful ratio; report the unnormalised cost.
  const double normaliser = root_area > 0.0 ? root_area : 1.0;
  stats.sah_cost = (costs.node * interior_area + costs.prim * leaf_area_times_prims) / normaliser;
  return stats;
}

std::string format_stats(const std::string& builder, const BvhStats& stats) {
  return fmt::format("{}: {} nodes ({} leaves, mean {:.2f} prims, max {}, depth {}), {:.1f} KiB, SAH {:.2f}, {:.2f} ms",
                     builder, stats.nodes, stats.leaves, stats.mean_leaf_size, stats.max_leaf_size, stats.max_depth,
                     static_cast<double>(stats.memory_bytes) / 1024.0, stats.sah_cost, stats.build_ms);
}

}  // namespace glint::accel
