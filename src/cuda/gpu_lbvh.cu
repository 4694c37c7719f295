#include "cuda/gpu_lbvh.cuh"

#include "cuda/radix_tree_split.h"

namespace glint::cuda::detail {
namespace {

// Karras's delta(i, j): the common prefix length of the keys (code << 32 | prim) at sorted
// positions i and j; -1 when j is outside [0, count). Keys are unique, so it is below 64.
struct KeyPrefix {
  const uint32_t* codes;
  const uint32_t* prims;
  int64_t count;

  __device__ int operator()(int64_t i, int64_t j) const {
    if (j < 0 || j >= count) return -1;
    const uint64_t a = (uint64_t{codes[i]} << 32) | prims[i];
    const uint64_t b = (uint64_t{codes[j]} << 32) | prims[j];
    return __clzll(static_cast<long long>(a ^ b));
  }
};

// The paper's Figure 4 for interior node i (one thread each, i in [0, count - 1); the search is in
// cuda/radix_tree_split.h). Interior node i is tree node count + i; the root is interior 0. Each
// node has one parent, so the parent writes never race. Subtree sizes follow from the key range.
__global__ void radix_tree_kernel(KeyPrefix delta, uint32_t leaf_count, uint2* children, uint32_t* parents,
                                  uint32_t* sizes) {
  const uint32_t thread = blockIdx.x * blockDim.x + threadIdx.x;
  if (thread + 1 >= leaf_count) return;
  const int64_t i = thread;
  const accel::RadixTreeNode range = accel::radix_tree_node(delta, i);
  const int64_t leaves = leaf_count;
  const auto node = static_cast<uint32_t>(leaves + i);
  const auto left = static_cast<uint32_t>(range.left_child(leaves));
  const auto right = static_cast<uint32_t>(range.right_child(leaves));
  children[i] = make_uint2(left, right);
  parents[left] = node;
  parents[right] = node;
  sizes[node] = static_cast<uint32_t>(2 * (range.last - range.first + 1) - 1);
}

// One thread per leaf: its box, then up the tree. The first thread to arrive at a node stops (the
// other child is not known to be done); the second computes the node's box and goes on, so every
// node is computed exactly once, after both children. __threadfence() before the arrival publishes
// this thread's boxes; the one after it orders the sibling's box (read from L2) after its arrival.
__global__ void fit_boxes_kernel(const Aabb* prim_boxes, const uint32_t* sorted_prims, uint32_t leaf_count,
                                 const uint2* children, const uint32_t* parents, uint32_t* arrivals,
                                 uint32_t* sizes, Aabb* boxes) {
  const uint32_t leaf = blockIdx.x * blockDim.x + threadIdx.x;
  if (leaf >= leaf_count) return;
  boxes[leaf] = prim_boxes[sorted_prims[leaf]];
  sizes[leaf] = 1;
  for (uint32_t node = parents[leaf]; node != kNoParent; node = parents[node]) {
    __threadfence();
    if (atomicAdd(&arrivals[node - leaf_count], 1u) == 0) return;
    __threadfence();
    const uint2 pair = children[node - leaf_count];
    boxes[node] = merged(load_box_from_l2(&boxes[pair.x]), load_box_from_l2(&boxes[pair.y]));
  }
}

}  // namespace

void build_lbvh_gpu(const Aabb* prim_boxes, uint32_t count, LbvhScratch& scratch, GpuBvh& out, cudaStream_t stream) {
  scratch.morton.sort(prim_boxes, count, stream);
  BuildTree& tree = scratch.tree;
  tree.reset(count, stream);
  if (count > 1) {
    const KeyPrefix delta{scratch.morton.sorted_codes(), scratch.morton.sorted_prims(), count};
    radix_tree_kernel<<<blocks_for(count - 1), kBlockSize, 0, stream>>>(delta, count, tree.children.data(),
                                                                        tree.parents.data(), tree.sizes.data());
    GLINT_CUDA_CHECK_LAUNCH();
    scratch.arrivals.resize(count - 1);
    scratch.arrivals.fill_zero(stream);
  }
  fit_boxes_kernel<<<blocks_for(count), kBlockSize, 0, stream>>>(
      prim_boxes, scratch.morton.sorted_prims(), count, tree.children.data(), tree.parents.data(),
      scratch.arrivals.data(), tree.sizes.data(), tree.boxes.data());
  GLINT_CUDA_CHECK_LAUNCH();
  const uint32_t root = count > 1 ? count : 0;  // interior node 0, or the lone leaf
  write_flat_layout(tree, scratch.morton.sorted_prims(), count, root, out, stream);
}

}  // namespace glint::cuda::detail
