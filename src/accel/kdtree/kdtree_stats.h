#pragma once
// Size and quality numbers of a kd-tree, in the same units as bvh_stats so the two can be compared.
#include "accel/bvh_stats.h"
#include "accel/kdtree/kdtree.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace glint::accel {

struct KdTreeStats {
  size_t nodes = 0;
  size_t interior_nodes = 0;
  size_t leaves = 0;
  size_t empty_leaves = 0;
  size_t references = 0;     // prim_indices entries (a triangle counts once per leaf holding it)
  size_t memory_bytes = 0;   // nodes + prim_indices
  uint32_t max_depth = 0;    // root = 1
  uint32_t max_leaf_size = 0;
  double sah_cost = 0.0;     // as bvh_stats, with the cells as the nodes' areas
  double build_ms = 0.0;     // copied from KdTree::build_ms
};

KdTreeStats compute_stats(const KdTree& tree, const SahCosts& costs = {});

// One line for logs, like format_stats for a BVH.
std::string format_stats(const std::string& name, const KdTreeStats& stats);

}  // namespace glint::accel
