#include "accel/wide/wide_bvh_validate.h"

#include "accel/bvh_node.h"
#include "accel/ray.h"
#include "core/error.h"

#include <algorithm>
#include <vector>

namespace glint::accel {
namespace {

bool inside(const Aabb& inner, const Aabb& outer) {
  return inner.empty() || (outer.contains(inner.min) && outer.contains(inner.max));
}

template <int N>
class WideValidator {
public:
  WideValidator(const WideBvh<N>& bvh, const TriangleMesh& mesh)
      : bvh_(bvh), mesh_(mesh), node_seen_(bvh.nodes.size(), 0), block_seen_(bvh.blocks.size(), 0),
        prim_seen_(mesh.triangle_count, 0) {}

  void run() {
    if (bvh_.prim_count != mesh_.triangle_count)
      fail("wide bvh: built over {} triangles, mesh has {}", bvh_.prim_count, mesh_.triangle_count);
    if (mesh_.triangle_count == 0) {
      if (!bvh_.nodes.empty() || !bvh_.blocks.empty()) fail("wide bvh: nodes or blocks but no triangles");
      return;
    }
    if (bvh_.nodes.empty()) fail("wide bvh: no nodes for {} triangles", mesh_.triangle_count);
    visit(0, bvh_.bounds, 1);
    for (size_t i = 0; i < node_seen_.size(); ++i)
      if (node_seen_[i] == 0) fail("wide bvh: node {} is not reachable", i);
    for (size_t i = 0; i < block_seen_.size(); ++i)
      if (block_seen_[i] == 0) fail("wide bvh: block {} belongs to no leaf", i);
    for (size_t i = 0; i < prim_seen_.size(); ++i)
      if (prim_seen_[i] == 0) fail("wide bvh: triangle {} is in no leaf", i);
    if (max_depth_ != bvh_.depth) fail("wide bvh: depth {} but bvh.depth says {}", max_depth_, bvh_.depth);
    if (leaves_ != bvh_.leaf_count) fail("wide bvh: {} leaves but leaf_count says {}", leaves_, bvh_.leaf_count);
  }

private:
  void visit(uint32_t index, const Aabb& box, uint32_t depth) {
    if (depth > kMaxBvhDepth) fail("wide bvh: node {} at depth {} beyond {}", index, depth, kMaxBvhDepth);
    if (node_seen_[index]++ != 0) fail("wide bvh: node {} reached twice", index);
    max_depth_ = std::max(max_depth_, depth);
    const WideNode<N>& node = bvh_.nodes[index];
    int used = 0;
    for (int lane = 0; lane < N; ++lane) {
      if (node.is_empty(lane)) {
        if (!node.child_bounds(lane).empty()) fail("wide bvh: node {} lane {} is empty but has a box", index, lane);
        continue;
      }
      if (used != lane) fail("wide bvh: node {} uses lane {} after an empty lane", index, lane);
      ++used;
      const Aabb child_box = node.child_bounds(lane);
      if (!inside(child_box, box)) fail("wide bvh: node {} lane {}: box outside its parent's", index, lane);
      if (node.is_leaf(lane)) {
        check_leaf(index, lane, node.child[lane], node.prim_count[lane], child_box);
      } else {
        if (node.child[lane] <= index || node.child[lane] >= bvh_.nodes.size())
          fail("wide bvh: node {} lane {}: child {} not after it or out of range", index, lane, node.child[lane]);
        visit(node.child[lane], child_box, depth + 1);
      }
    }
    const bool single_leaf_root = index == 0 && used == 1 && node.is_leaf(0);
    if (used < 2 && !single_leaf_root) fail("wide bvh: node {} has {} children", index, used);
  }

  void check_leaf(uint32_t index, int lane, uint32_t first_block, uint32_t count, const Aabb& box) {
    ++leaves_;
    const uint32_t block_count = wide_block_count<N>(count);
    if (size_t{first_block} + block_count > bvh_.blocks.size())
      fail("wide bvh: node {} lane {}: blocks {}+{} past the {} blocks", index, lane, first_block, block_count,
           bvh_.blocks.size());
    for (uint32_t slot = 0; slot < block_count * N; ++slot) {
      const uint32_t b = first_block + slot / N;
      const uint32_t l = slot % N;
      if (l == 0 && block_seen_[b]++ != 0) fail("wide bvh: block {} owned by two leaves", b);
      const TriangleBlock<N>& block = bvh_.blocks[b];
      const uint32_t prim = block.prim[l];
      if (slot >= count) {
        if (prim != Hit::kInvalidIndex) fail("wide bvh: block {} lane {} past the leaf's count holds {}", b, l, prim);
        continue;
      }
      if (prim >= mesh_.triangle_count) fail("wide bvh: block {} lane {} holds triangle {}", b, l, prim);
      if (prim_seen_[prim]++ != 0) fail("wide bvh: triangle {} in two lanes", prim);
      const Triangle tri = mesh_.triangle(prim);
      const vec3 corners[3] = {tri.v0, tri.v1, tri.v2};
      for (int c = 0; c < 3; ++c) {
        const vec3 gathered(block.v[c][0][l], block.v[c][1][l], block.v[c][2][l]);
        if (gathered != corners[c]) fail("wide bvh: block {} lane {}: corner {} differs from the mesh", b, l, c);
      }
      if (!inside(tri.bounds(), box)) fail("wide bvh: triangle {} outside its leaf's box", prim);
    }
  }

  const WideBvh<N>& bvh_;
  const TriangleMesh& mesh_;
  std::vector<uint8_t> node_seen_, block_seen_, prim_seen_;
  uint32_t max_depth_ = 0;
  uint32_t leaves_ = 0;
};

}  // namespace

template <int N>
void validate_wide_bvh(const WideBvh<N>& bvh, const TriangleMesh& mesh) {
  WideValidator<N>(bvh, mesh).run();
}

template void validate_wide_bvh<4>(const WideBvh<4>&, const TriangleMesh&);
template void validate_wide_bvh<8>(const WideBvh<8>&, const TriangleMesh&);

}  // namespace glint::accel
