#pragma once
// Wide (4- or 8-ary) BVHs for SIMD traversal on the CPU, collapsed from any binary Bvh
// (wide_bvh_collapse.h) and traced with SSE / AVX2 kernels (wide_bvh_trace.h).
//
// Layout (structure of arrays, so one aligned load fetches one plane of all N children):
//
//   WideNode<N>       bounds[axis][0 = min, 1 = max][child]   3 * 2 * N floats
//                     child[N]       interior child: index into nodes
//                                    leaf child:     index of its first TriangleBlock
//                                    empty slot:     kEmptySlot (its box is empty, so it never hits)
//                     prim_count[N]  0 for an interior child, the leaf's triangle count otherwise;
//                                    a leaf of c triangles owns ceil(c / N) consecutive blocks
//   TriangleBlock<N>  v[corner][axis][lane], the three corners of N triangles gathered from the
//                     mesh, and prim[lane], the original triangle index (kInvalidIndex in padding
//                     lanes, whose corners repeat the last real triangle of the leaf).
//
// The node's own box lives in its parent's lanes (the root's in WideBvh::bounds), as in Embree's
// BVH4/BVH8. Nodes are stored in depth-first order with children after their parents, so refit
// can sweep the array in reverse. 4-wide nodes are 128 B and 8-wide nodes 256 B, both aligned to
// cache lines; blocks are 160 B / 320 B. The triangles are copied, so tracing needs no mesh.
#include "core/math.h"

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

namespace glint::accel {

template <int N>
struct alignas(64) WideNode {
  static_assert(N == 4 || N == 8, "wide BVHs are 4- or 8-wide");
  static constexpr uint32_t kEmptySlot = 0xFFFFFFFFu;

  float bounds[3][2][N];
  uint32_t child[N];
  uint32_t prim_count[N];

  bool is_empty(int lane) const { return child[lane] == kEmptySlot; }
  bool is_leaf(int lane) const { return prim_count[lane] != 0; }
  Aabb child_bounds(int lane) const {
    return Aabb{vec3(bounds[0][0][lane], bounds[1][0][lane], bounds[2][0][lane]),
                vec3(bounds[0][1][lane], bounds[1][1][lane], bounds[2][1][lane])};
  }
  void set_child_bounds(int lane, const Aabb& box) {
    for (int axis = 0; axis < 3; ++axis) {
      bounds[axis][0][lane] = box.min[axis];
      bounds[axis][1][lane] = box.max[axis];
    }
  }
};

template <int N>
struct alignas(32) TriangleBlock {
  float v[3][3][N];
  uint32_t prim[N];
};

static_assert(sizeof(WideNode<4>) == 128 && sizeof(WideNode<8>) == 256);
static_assert(sizeof(TriangleBlock<4>) == 160 && sizeof(TriangleBlock<8>) == 320);
static_assert(std::is_trivially_copyable_v<WideNode<8>> && std::is_trivially_copyable_v<TriangleBlock<8>>);

// Triangles per leaf block: one SIMD test covers a whole block.
template <int N>
constexpr uint32_t wide_block_count(uint32_t prim_count) {
  return (prim_count + N - 1) / N;
}

template <int N>
struct WideBvh {
  static constexpr int kWidth = N;

  std::vector<WideNode<N>> nodes;          // nodes[0] is the root; empty when there are no triangles
  std::vector<TriangleBlock<N>> blocks;    // leaf triangles, each leaf's blocks consecutive
  Aabb bounds;                             // the root's box
  uint32_t prim_count = 0;                 // triangles of the mesh it was built over
  uint32_t depth = 0;                      // wide levels, root = 1; at most kMaxBvhDepth
  uint32_t leaf_count = 0;
  bool refittable = true;                  // copied from the binary BVH
  std::string builder;                     // the binary builder it was collapsed from
  double build_ms = 0.0;                   // the binary build (copied)
  double collapse_ms = 0.0;                // collapse + triangle gather (steady_clock)
};

using WideBvh4 = WideBvh<4>;
using WideBvh8 = WideBvh<8>;

}  // namespace glint::accel
