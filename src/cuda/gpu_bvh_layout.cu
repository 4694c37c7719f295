#include "cuda/gpu_bvh_layout.cuh"

namespace glint::cuda::detail {
namespace {

// The flat layout is a pre-order of sibling pairs: a node at position p whose children pair starts
// at c (c > p) has its left child at c and its right child at c + 1; the left child's own pair
// starts at c + 2 and the right child's after the left child's descendants, at
// c + 2 + (size(left) - 1). So the start of a node's pair is 1 (the root's) plus, for every edge on
// its path up to the root, 2 + (size of the left sibling - 1 when the edge's lower end is a right
// child). One thread per tree node sums that path (at most kMaxBvhDepth steps for the builders'
// trees), reading only data earlier kernels finished, so no thread waits for another.
__global__ void flat_layout_kernel(const uint2* children, const uint32_t* parents, const uint32_t* sizes,
                                   const Aabb* boxes, const uint32_t* sorted_prims, uint32_t leaf_count,
                                   uint32_t root, accel::BvhNode* nodes, uint32_t* prim_indices,
                                   uint32_t* flat_parents) {
  const uint32_t node = blockIdx.x * blockDim.x + threadIdx.x;
  if (node >= 2 * leaf_count - 1) return;
  uint32_t pair_start = 1;      // where this node's children go
  uint32_t own_step = 0;        // what the edge to its parent added
  bool is_right_child = false;
  uint32_t child = node;
  for (uint32_t parent = parents[node]; parent != kNoParent; child = parent, parent = parents[parent]) {
    const uint2 pair = children[parent - leaf_count];
    const bool right = child == pair.y;
    const uint32_t step = 2 + (right ? sizes[pair.x] - 1 : 0);
    if (child == node) {
      own_step = step;
      is_right_child = right;
    }
    pair_start += step;
  }
  // The parent's pair starts at pair_start - own_step: the left child sits there, the right one after.
  const uint32_t position = node == root ? 0 : pair_start - own_step + (is_right_child ? 1 : 0);

  accel::BvhNode flat;
  flat.set_bounds(boxes[node]);
  if (node < leaf_count) {
    flat.first = node;
    flat.prim_count = 1;
    prim_indices[node] = sorted_prims[node];
  } else {
    flat.first = pair_start;
    flat.prim_count = 0;
    flat_parents[pair_start] = position;
    flat_parents[pair_start + 1] = position;
  }
  if (node == root) flat_parents[0] = kNoParent;
  nodes[position] = flat;
}

}  // namespace

void BuildTree::reset(uint32_t leaf_count, cudaStream_t stream) {
  const std::size_t node_count = 2 * std::size_t{leaf_count} - 1;
  children.resize(leaf_count - 1);
  parents.resize(node_count);
  sizes.resize(node_count);
  boxes.resize(node_count);
  static_assert(kNoParent == 0xFFFFFFFFu, "parents are reset with a byte memset of 0xFF");
  GLINT_CUDA_CHECK(cudaMemsetAsync(parents.data(), 0xFF, parents.bytes(), stream));
}

void write_flat_layout(const BuildTree& tree, const uint32_t* sorted_prims, uint32_t leaf_count, uint32_t root,
                       GpuBvh& out, cudaStream_t stream) {
  const uint32_t node_count = 2 * leaf_count - 1;
  flat_layout_kernel<<<blocks_for(node_count), kBlockSize, 0, stream>>>(
      tree.children.data(), tree.parents.data(), tree.sizes.data(), tree.boxes.data(), sorted_prims, leaf_count, root,
      out.nodes.data(), out.prim_indices.data(), out.parents.data());
  GLINT_CUDA_CHECK_LAUNCH();
}

}  // namespace glint::cuda::detail
