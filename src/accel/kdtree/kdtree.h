#pragma once
// SAH kd-tree over triangles (OptiX 3/4 "TriangleKdTree"): layout and builder entry point. The
// builder is Wald & Havran, "On building fast kd-trees for ray tracing, and on doing that in
// O(N log N)" (RT 2006); traversal is in kdtree_traverse.h, batches in kdtree_trace.h.
//
// Unlike a BVH, a kd-tree partitions space: a triangle crossing a split plane is referenced by both
// children, so leaves hold references and the structure cannot be refitted (refit() below says so).
#include "accel/triangle_mesh.h"
#include "core/math.h"

#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace glint::accel {

// 8 bytes, as in pbrt: the below child of an interior node is the next node in the array, the above
// child's index is stored; a leaf stores its prim count and the offset of its first prim_indices
// entry. Low 2 bits of `bits`: split axis 0..2, or 3 for a leaf; the upper 30: above child index
// (interior) or prim count (leaf).
struct KdNode {
  static constexpr uint32_t kLeafTag = 3;

  union {
    float split;           // interior: the plane x[axis] = split
    uint32_t first_prim;   // leaf: first prim_indices entry
  };
  uint32_t bits;

  GLINT_HOST_DEVICE bool is_leaf() const { return (bits & 3u) == kLeafTag; }
  GLINT_HOST_DEVICE int axis() const { return static_cast<int>(bits & 3u); }
  GLINT_HOST_DEVICE uint32_t above_child() const { return bits >> 2; }
  GLINT_HOST_DEVICE uint32_t prim_count() const { return bits >> 2; }

  static KdNode interior(int axis, float position, uint32_t above) {
    KdNode node;
    node.split = position;
    node.bits = (above << 2) | static_cast<uint32_t>(axis);
    return node;
  }
  static KdNode leaf(uint32_t first, uint32_t count) {
    KdNode node;
    node.first_prim = first;
    node.bits = (count << 2) | kLeafTag;
    return node;
  }
};

static_assert(sizeof(KdNode) == 8 && std::is_trivially_copyable_v<KdNode>);

// Node indices and leaf counts have 30 bits.
inline constexpr uint32_t kMaxKdIndex = (1u << 30) - 1;
// Builders never go deeper (root = depth 1); traversal's stack has this many entries.
inline constexpr uint32_t kMaxKdDepth = 64;

// What traversal needs, copyable to the device once the arrays live there.
struct KdTreeView {
  const KdNode* nodes = nullptr;
  const uint32_t* prim_indices = nullptr;
  uint32_t node_count = 0;  // 0: empty tree, every ray misses
  Aabb bounds;              // the root cell
};

static_assert(std::is_trivially_copyable_v<KdTreeView>);

struct KdTree {
  std::vector<KdNode> nodes;           // nodes[0] is the root; empty when there are no triangles
  std::vector<uint32_t> prim_indices;  // leaf references -> original triangle index
  Aabb bounds;                         // root cell: the bounds of all triangles
  uint32_t prim_count = 0;             // triangles it was built over
  uint32_t depth = 0;                  // levels, root = 1
  double build_ms = 0.0;               // steady_clock wall time of the build

  KdTreeView view() const { return {nodes.data(), prim_indices.data(), static_cast<uint32_t>(nodes.size()), bounds}; }
};

struct KdTreeOptions {
  // SAH: cost(split) = traversal_cost + intersection_cost * (P_L N_L + P_R N_R) * (1 - bonus), with
  // bonus = empty_bonus when one side is empty (cutting off empty space pays); a node becomes a
  // leaf when no split is cheaper than intersection_cost * N. Wald & Havran use K_T = 15, K_I = 20.
  float traversal_cost = 1.0f;
  float intersection_cost = 1.5f;
  float empty_bonus = 0.2f;  // in [0, 1)
  // 0: the usual 8 + 1.3 log2(N), at most kMaxKdDepth.
  uint32_t max_depth = 0;
  // Nodes with at least this many triangles build their children as parallel TBB tasks.
  uint32_t parallel_threshold = 4096;
};

// glint::Error on a non-finite vertex, more than 2^30 - 1 triangles or invalid options.
KdTree build_kdtree(const TriangleMesh& mesh, const KdTreeOptions& options = {});

// The depth limit a build over `triangle_count` triangles uses with these options.
uint32_t kdtree_depth_limit(uint32_t triangle_count, const KdTreeOptions& options);

// A kd-tree's leaves reference every triangle in every cell it crosses: moved vertices change which
// cells those are, so there is no refit. Always throws glint::Error (rebuild instead); it exists so
// that code written for refittable structures fails loudly, not silently.
[[noreturn]] void refit(KdTree& tree, const TriangleMesh& mesh);

}  // namespace glint::accel
