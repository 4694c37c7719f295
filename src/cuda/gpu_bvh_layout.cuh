#pragma once
// Shared by the GPU builders (gpu_lbvh.cu, gpu_ploc.cu) and refit (gpu_bvh_refit.cu): launch sizes,
// box loads for the bottom-up passes, and the binary tree a builder makes before it becomes the
// flat layout of accel::BvhNode (write_flat_layout). CUDA-only header: include it from .cu files.
#include "cuda/gpu_bvh.h"

#include <cstdint>

namespace glint::cuda::detail {

inline constexpr uint32_t kBlockSize = 256;

inline unsigned int blocks_for(uint32_t count) { return (count + kBlockSize - 1) / kBlockSize; }

__device__ inline Aabb merged(Aabb a, const Aabb& b) {
  a.extend(b);
  return a;
}

// Loads through L2 only (ld.global.cg). The bottom-up passes read a sibling's box that another
// thread, possibly on another SM, wrote during the same kernel; L1 is not coherent between SMs, so
// these reads must not be served from it. The writer's __threadfence() before its atomic arrival
// and the reader's after its own make the write visible in L2 first.
__device__ inline Aabb load_box_from_l2(const Aabb* box) {
  Aabb loaded;
  loaded.min = vec3(__ldcg(&box->min.x), __ldcg(&box->min.y), __ldcg(&box->min.z));
  loaded.max = vec3(__ldcg(&box->max.x), __ldcg(&box->max.y), __ldcg(&box->max.z));
  return loaded;
}

__device__ inline Aabb load_node_box_from_l2(const accel::BvhNode* node) {
  Aabb loaded;
  loaded.min = vec3(__ldcg(&node->bounds_min.x), __ldcg(&node->bounds_min.y), __ldcg(&node->bounds_min.z));
  loaded.max = vec3(__ldcg(&node->bounds_max.x), __ldcg(&node->bounds_max.y), __ldcg(&node->bounds_max.z));
  return loaded;
}

// The tree a builder makes over leaf_count Morton-sorted primitives, before layout: nodes
// [0, leaf_count) are the leaves (leaf k holds the k-th primitive in Morton order), nodes
// [leaf_count, 2 leaf_count - 1) the interior nodes, in whatever order the builder creates them.
struct BuildTree {
  DeviceBuffer<uint2> children;    // per interior node (index node - leaf_count): x = left, y = right
  DeviceBuffer<uint32_t> parents;  // per node; kNoParent for the root
  DeviceBuffer<uint32_t> sizes;    // per node: nodes in its subtree (1 for a leaf)
  DeviceBuffer<Aabb> boxes;        // per node

  // Sizes every array for leaf_count >= 1 leaves and sets every parent to kNoParent, so the root's
  // stays that way (builders write the parents of children only).
  void reset(uint32_t leaf_count, cudaStream_t stream);
};

// Writes `out` (nodes, prim_indices, parents; sized by the caller to 2 leaf_count - 1, leaf_count
// and 2 leaf_count - 1) from `tree`: root at 0, each interior node's children adjacent and after it
// (a pre-order of sibling pairs), one primitive per leaf with leaf k at slot k, so prim_indices is
// `sorted_prims` (the Morton order). Needs every parent, child, size and box of the tree.
void write_flat_layout(const BuildTree& tree, const uint32_t* sorted_prims, uint32_t leaf_count, uint32_t root,
                       GpuBvh& out, cudaStream_t stream);

}  // namespace glint::cuda::detail
