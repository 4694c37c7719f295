#pragma once
// Size and quality numbers of a BVH, the same for every builder so they can be compared.
#include "accel/builders/build_options.h"
#include "accel/bvh.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace glint::accel {

// SAH cost (Aila, Karras, Laine, "On Quality Metrics of Bounding Volume Hierarchies", HPG 2013):
//   cost = (C_node * sum over interior nodes A(n) + C_prim * sum over leaves A(l) * N(l)) / A(root)
// with A the surface area and N(l) the primitives in leaf l. The paper (and the defaults here,
// matching BuildOptions) use C_node = 1.2 and C_prim = 1 (their C_l, the per-leaf cost, is 0).
struct SahCosts {
  float node = 1.2f;
  float prim = 1.0f;
};

struct BvhStats {
  size_t nodes = 0;
  size_t interior_nodes = 0;
  size_t leaves = 0;
  size_t primitives = 0;        // prim_indices entries
  size_t memory_bytes = 0;      // nodes + prim_indices
  uint32_t max_depth = 0;       // root = 1
  uint32_t max_leaf_size = 0;
  double mean_leaf_size = 0.0;
  double sah_cost = 0.0;
  double build_ms = 0.0;        // copied from Bvh::build_ms
};

BvhStats compute_stats(const Bvh& bvh, const SahCosts& costs = {});

// The costs `build` used (its traversal and intersection costs), as compute_stats takes them.
inline SahCosts sah_costs(const BuildOptions& build) { return {build.traversal_cost, build.intersection_cost}; }

// The SAH cost of `bvh` with the costs `build` used: what the automatic update policy compares
// before and after refits (rt/update_decision.h).
double sah_cost(const Bvh& bvh, const BuildOptions& build);

// One line for logs: "sah: 1023 nodes (512 leaves, depth 12), 20.4 KiB, SAH 34.2, 1.8 ms".
std::string format_stats(const std::string& builder, const BvhStats& stats);

}  // namespace glint::accel
