#include "accel/wide/wide_bvh_collapse.h"

#include "accel/builders/primitive_bounds.h"
#include "accel/ray.h"
#include "core/error.h"
#include "core/stopwatch.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

namespace glint::accel {
namespace {

// What collapse needs to know of every binary subtree: its triangle count and, when its leaves
// cover one run of prim_indices slots, where that run starts.
struct SubtreeRange {
  uint32_t first = 0;
  uint32_t count = 0;
  bool consecutive = true;
};

std::vector<SubtreeRange> subtree_ranges(const Bvh& bvh) {
  std::vector<SubtreeRange> ranges(bvh.nodes.size());
  // Children after parents: a reverse sweep sees both children first.
  for (size_t i = bvh.nodes.size(); i-- > 0;) {
    const BvhNode& node = bvh.nodes[i];
    if (node.is_leaf()) {
      if (size_t{node.first} + node.prim_count > bvh.prim_indices.size())
        fail("accel: collapse: leaf {} addresses slots past the {} primitives", i, bvh.prim_indices.size());
      ranges[i] = {node.first, node.prim_count, true};
      continue;
    }
    if (node.left() <= i || node.right() >= bvh.nodes.size())
      fail("accel: collapse: node {} has children at {}, not after it", i, node.left());
    const SubtreeRange& a = ranges[node.left()];
    const SubtreeRange& b = ranges[node.right()];
    const bool touching = a.first + a.count == b.first || b.first + b.count == a.first;
    ranges[i] = {std::min(a.first, b.first), a.count + b.count, a.consecutive && b.consecutive && touching};
  }
  return ranges;
}

template <int N>
class Collapser {
public:
  Collapser(const Bvh& bvh, uint32_t merge_leaf_size, WideBvh<N>& out)
      : bvh_(bvh), ranges_(subtree_ranges(bvh)), merge_leaf_size_(merge_leaf_size), out_(out) {}

  uint32_t emit_node(uint32_t binary_index, uint32_t depth) {
    out_.depth = std::max(out_.depth, depth);
    if (depth > kMaxBvhDepth) fail("accel: collapse: wide depth {} exceeds {}", depth, kMaxBvhDepth);
    const auto node_index = static_cast<uint32_t>(out_.nodes.size());
    out_.nodes.push_back(empty_node());

    // Open the largest-area interior child until the node is full.
    uint32_t children[N];
    int child_count = 0;
    if (is_wide_leaf(binary_index)) {
      children[child_count++] = binary_index;
    } else {
      children[child_count++] = bvh_.nodes[binary_index].left();
      children[child_count++] = bvh_.nodes[binary_index].right();
    }
    while (child_count < N) {
      int widest = -1;
      float widest_area = -1.0f;
      for (int i = 0; i < child_count; ++i) {
        if (is_wide_leaf(children[i])) continue;
        const float area = half_area(bvh_.nodes[children[i]].bounds());
        if (area > widest_area) {
          widest = i;
          widest_area = area;
        }
      }
      if (widest < 0) break;
      const BvhNode& opened = bvh_.nodes[children[widest]];
      children[widest] = opened.left();
      children[child_count++] = opened.right();
    }

    for (int lane = 0; lane < child_count; ++lane) {
      const uint32_t child = children[lane];
      uint32_t reference, prim_count = 0;
      if (is_wide_leaf(child)) {
        prim_count = ranges_[child].count;
        reference = emit_leaf(ranges_[child]);
      } else {
        reference = emit_node(child, depth + 1);
      }
      WideNode<N>& node = out_.nodes[node_index];  // emit_node may have reallocated
      node.set_child_bounds(lane, bvh_.nodes[child].bounds());
      node.child[lane] = reference;
      node.prim_count[lane] = prim_count;
    }
    return node_index;
  }

private:
  static WideNode<N> empty_node() {
    WideNode<N> node;
    for (int lane = 0; lane < N; ++lane) {
      node.set_child_bounds(lane, Aabb{});
      node.child[lane] = WideNode<N>::kEmptySlot;
      node.prim_count[lane] = 0;
    }
    return node;
  }

  bool is_wide_leaf(uint32_t binary_index) const {
    if (bvh_.nodes[binary_index].is_leaf()) return true;
    const SubtreeRange& range = ranges_[binary_index];
    return range.consecutive && range.count <= merge_leaf_size_;
  }

  uint32_t emit_leaf(const SubtreeRange& range) {
    const auto first_block = static_cast<uint32_t>(out_.blocks.size());
    for (uint32_t begin = 0; begin < range.count; begin += N) {
      TriangleBlock<N>& block = out_.blocks.emplace_back();
      for (uint32_t lane = 0; lane < N; ++lane) {
        const uint32_t slot = begin + lane;
        block.prim[lane] = slot < range.count ? bvh_.prim_indices[range.first + slot] : Hit::kInvalidIndex;
      }
    }
    ++out_.leaf_count;
    return first_block;
  }

  const Bvh& bvh_;
  std::vector<SubtreeRange> ranges_;
  uint32_t merge_leaf_size_;
  WideBvh<N>& out_;
};

}  // namespace

template <int N>
WideBvh<N> collapse_to_wide(const Bvh& bvh, const TriangleMesh& mesh, const WideCollapseOptions& options) {
  const Stopwatch watch;
  // Leaves of a spatial-split BVH (sbvh) hold clipped references: a triangle may sit in several
  // leaves, and its gathered copy would be the whole triangle, not the clipped part the leaf box
  // bounds. Wide BVHs are made from builders without spatial splits.
  if (!bvh.refittable)
    fail("accel: collapse: the '{}' BVH holds split references; collapse a BVH without spatial splits "
         "(median, sah, lbvh, trbvh, ploc)", bvh.builder);
  if (bvh.prim_indices.size() != mesh.triangle_count)
    fail("accel: collapse: BVH built over {} primitives given a mesh of {} triangles", bvh.prim_indices.size(),
         mesh.triangle_count);
  if (bvh.depth > kMaxBvhDepth) fail("accel: collapse: BVH depth {} exceeds {}", bvh.depth, kMaxBvhDepth);
  WideBvh<N> wide;
  wide.prim_count = mesh.triangle_count;
  wide.refittable = bvh.refittable;
  wide.builder = bvh.builder;
  wide.build_ms = bvh.build_ms;
  if (!bvh.nodes.empty()) {
    const uint32_t merge = options.merge_leaf_size == WideCollapseOptions::kMergeToWidth ? N : options.merge_leaf_size;
    Collapser<N>(bvh, merge, wide).emit_node(0, 1);
    wide.bounds = bvh.bounds();
    gather_wide_triangles(wide, mesh);
  }
  wide.collapse_ms = watch.elapsed_ms();
  return wide;
}

template <int N>
void gather_wide_triangles(WideBvh<N>& wide, const TriangleMesh& mesh) {
  if (wide.prim_count != mesh.triangle_count)
    fail("accel: wide BVH over {} triangles given a mesh of {}", wide.prim_count, mesh.triangle_count);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, wide.blocks.size(), 1024), [&](const auto& range) {
    for (size_t b = range.begin(); b != range.end(); ++b) {
      TriangleBlock<N>& block = wide.blocks[b];
      Triangle tri{};
      for (int lane = 0; lane < N; ++lane) {
        // Padding lanes (after the real ones) repeat the last triangle: finite values, masked off.
        if (block.prim[lane] != Hit::kInvalidIndex) {
          if (block.prim[lane] >= mesh.triangle_count)
            fail("accel: wide BVH block {} references triangle {} of {}", b, block.prim[lane], mesh.triangle_count);
          tri = mesh.triangle(block.prim[lane]);
        }
        for (int axis = 0; axis < 3; ++axis) {
          block.v[0][axis][lane] = tri.v0[axis];
          block.v[1][axis][lane] = tri.v1[axis];
          block.v[2][axis][lane] = tri.v2[axis];
        }
      }
    }
  });
}

template WideBvh<4> collapse_to_wide<4>(const Bvh&, const TriangleMesh&, const WideCollapseOptions&);
template WideBvh<8> collapse_to_wide<8>(const Bvh&, const TriangleMesh&, const WideCollapseOptions&);
template void gather_wide_triangles<4>(WideBvh<4>&, const TriangleMesh&);
template void gather_wide_triangles<8>(WideBvh<8>&, const TriangleMesh&);

}  // namespace glint::accel
