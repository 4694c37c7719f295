#pragma once
// A built BVH: the node array, the primitive permutation its leaves index, and how it was made.
#include "accel/bvh_node.h"
#include "accel/unzeroed_vector.h"

#include <cstdint>
#include <string>
#include <vector>

namespace glint::accel {

struct Bvh {
  // Builders size these with resize(n) and fill them in parallel (unzeroed_vector.h says why they
  // are not plain std::vectors).
  UnzeroedVector<BvhNode> nodes;         // nodes[0] is the root; empty when there are no primitives
  UnzeroedVector<uint32_t> prim_indices;  // leaf slots -> original primitive index
  // False for structures whose leaves reference split (clipped) primitive references, e.g. SBVH:
  // moving vertices invalidates those, so refit() refuses them.
  bool refittable = true;
  uint32_t depth = 0;       // levels, root = 1; at most kMaxBvhDepth
  std::string builder;      // "none", "median", "sah", ...
  double build_ms = 0.0;    // wall time of the build, set by build_bvh (builder.h), which times the builders

  BvhView view() const {
    return {nodes.data(), prim_indices.data(), static_cast<uint32_t>(nodes.size())};
  }
  Aabb bounds() const { return nodes.empty() ? Aabb{} : nodes[0].bounds(); }
};

}  // namespace glint::accel
