#include "accel/wide_bvh_refit.h"

#include "accel/wide_bvh_collapse.h"
#include "core/error.h"

#include <tbb/task_group.h>

#include <array>
#include <bit>

namespace glint::accel {
namespace {

// Levels whose nodes fork their lanes as tasks: about one task per 1024 lanes below the forks (more
// tasks than cores even on a few thousand nodes, so stealing evens out unbalanced trees), none for a
// small tree.
template <int N>
uint32_t task_levels(size_t nodes) {
  constexpr auto fork_bits = static_cast<uint32_t>(std::bit_width(static_cast<unsigned>(N)) - 1);  // log2(N)
  const auto bits = static_cast<uint32_t>(std::bit_width(nodes * N / 1024));
  return (bits + fork_bits - 1) / fork_bits;
}

// One depth-first pass over the wide tree: a leaf lane re-gathers its triangle blocks from the mesh
// and bounds them, an interior lane takes its child node's box, written on the way back up. Nodes
// near the root fork their lanes as parallel tasks.
template <int N>
struct WideRefitter {
  WideBvh<N>& bvh;
  const TriangleMesh& mesh;
  uint32_t task_levels;

  Aabb refit_leaf(uint32_t first_block, uint32_t prim_count) const {
    Aabb box;
    for (uint32_t slot = 0; slot < prim_count; ++slot) {
      const uint32_t lane = slot % N;
      if (lane == 0) gather_wide_block(bvh, first_block + slot / N, mesh);
      const TriangleBlock<N>& block = bvh.blocks[first_block + slot / N];
      for (int corner = 0; corner < 3; ++corner)
        box.extend(vec3(block.v[corner][0][lane], block.v[corner][1][lane], block.v[corner][2][lane]));
    }
    return box;
  }

  Aabb refit(uint32_t index, uint32_t level) const {
    WideNode<N>& node = bvh.nodes[index];
    std::array<Aabb, N> boxes;
    const auto refit_lane = [&](int lane) {
      if (node.is_leaf(lane)) {
        boxes[static_cast<size_t>(lane)] = refit_leaf(node.child[lane], node.prim_count[lane]);
        return;
      }
      boxes[static_cast<size_t>(lane)] = refit(node.child[lane], level + 1);
    };
    for (int lane = 0; lane < N; ++lane) {
      if (node.is_empty(lane) || node.is_leaf(lane)) continue;
      if (node.child[lane] <= index || node.child[lane] >= bvh.nodes.size())
        fail("accel: refit: wide node {} has a child at {}, not after it", index, node.child[lane]);
      if (level >= kMaxBvhDepth) fail("accel: refit: the wide BVH is deeper than {} levels", kMaxBvhDepth);
    }
    if (level < task_levels) {
      tbb::task_group group;
      for (int lane = 0; lane < N; ++lane)
        if (!node.is_empty(lane)) group.run([&refit_lane, lane] { refit_lane(lane); });
      group.wait();
    } else {
      for (int lane = 0; lane < N; ++lane)
        if (!node.is_empty(lane)) refit_lane(lane);
    }
    Aabb box;
    for (int lane = 0; lane < N; ++lane) {
      if (node.is_empty(lane)) continue;
      node.set_child_bounds(lane, boxes[static_cast<size_t>(lane)]);
      box.extend(boxes[static_cast<size_t>(lane)]);
    }
    return box;
  }
};

template <int N>
void refit_wide(WideBvh<N>& bvh, const TriangleMesh& mesh) {
  if (!bvh.refittable)
    fail("accel: refit: this wide BVH (from builder '{}') is not refittable; rebuild it instead", bvh.builder);
  if (mesh.triangle_count != bvh.prim_count)
    fail("accel: refit: mesh of {} triangles for a wide BVH over {}", mesh.triangle_count, bvh.prim_count);
  if (bvh.nodes.empty()) {
    bvh.bounds = Aabb{};
    return;
  }
  const WideRefitter<N> refitter{bvh, mesh, task_levels<N>(bvh.nodes.size())};
  bvh.bounds = refitter.refit(0, 1);
}

}  // namespace

void refit(WideBvh4& bvh, const TriangleMesh& mesh) { refit_wide(bvh, mesh); }
void refit(WideBvh8& bvh, const TriangleMesh& mesh) { refit_wide(bvh, mesh); }

}  // namespace glint::accel
