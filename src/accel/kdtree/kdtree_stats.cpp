#include "accel/kdtree/kdtree_stats.h"

#include "accel/builders/primitive_bounds.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace glint::accel {

KdTreeStats compute_stats(const KdTree& tree, const SahCosts& costs) {
  KdTreeStats stats;
  stats.nodes = tree.nodes.size();
  stats.references = tree.prim_indices.size();
  stats.memory_bytes = tree.nodes.size() * sizeof(KdNode) + tree.prim_indices.size() * sizeof(uint32_t);
  stats.build_ms = tree.build_ms;
  if (tree.nodes.empty()) return stats;

  struct Item {
    uint32_t node;
    uint32_t depth;
    Aabb cell;
  };
  double interior_area = 0.0, leaf_area_times_prims = 0.0;
  std::vector<Item> stack{{0u, 1u, tree.bounds}};
  while (!stack.empty()) {
    const Item item = stack.back();
    stack.pop_back();
    const KdNode& node = tree.nodes[item.node];
    stats.max_depth = std::max(stats.max_depth, item.depth);
    const double area = half_area(item.cell);
    if (node.is_leaf()) {
      ++stats.leaves;
      stats.empty_leaves += node.prim_count() == 0 ? 1 : 0;
      stats.max_leaf_size = std::max(stats.max_leaf_size, node.prim_count());
      leaf_area_times_prims += area * node.prim_count();
      continue;
    }
    ++stats.interior_nodes;
    interior_area += area;
    Aabb below = item.cell, above = item.cell;
    below.max[node.axis()] = node.split;
    above.min[node.axis()] = node.split;
    stack.push_back({item.node + 1, item.depth + 1, below});
    stack.push_back({node.above_child(), item.depth + 1, above});
  }
  const double root_area = half_area(tree.bounds);
  const double normaliser = root_area > 0.0 ? root_area : 1.0;
  stats.sah_cost = (costs.node * interior_area + costs.prim * leaf_area_times_prims) / normaliser;
  return stats;
}

std::string format_stats(const std::string& name, const KdTreeStats& stats) {
  return fmt::format("{}: {} nodes ({} leaves, {} empty, depth {}), {} references, max leaf {}, {:.1f} KiB, SAH {:.2f}, "
                     "{:.2f} ms",
                     name, stats.nodes, stats.leaves, stats.empty_leaves, stats.max_depth, stats.references,
                     stats.max_leaf_size, static_cast<double>(stats.memory_bytes) / 1024.0, stats.sah_cost,
                     stats.build_ms);
}

}  // namespace glint::accel
