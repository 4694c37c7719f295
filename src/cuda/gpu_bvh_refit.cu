#include "cuda/gpu_bvh_build.h"

#include "cuda/gpu_bvh_layout.cuh"

#include <string>

namespace glint::cuda {
namespace {

// One thread per node; leaves take the union of their primitives' boxes, then climb through the
// parent links. The first thread to arrive at a node stops; the second (its sibling subtree is
// done) computes the node's box from both children and goes on. __threadfence() before the arrival
// publishes this thread's boxes; the one after it orders the sibling's box, read from L2, after the
// arrival. Only the bounds are written: the topology (first, prim_count) is read with plain loads.
__global__ void refit_kernel(accel::BvhNode* nodes, const uint32_t* prim_indices, const uint32_t* parents,
                             const Aabb* prim_boxes, uint32_t node_count, uint32_t* arrivals) {
  const uint32_t leaf = blockIdx.x * blockDim.x + threadIdx.x;
  if (leaf >= node_count) return;
  const uint32_t first = nodes[leaf].first, prim_count = nodes[leaf].prim_count;
  if (prim_count == 0) return;
  Aabb box;
  for (uint32_t slot = first; slot != first + prim_count; ++slot) box.extend(prim_boxes[prim_indices[slot]]);
  nodes[leaf].bounds_min = box.min;
  nodes[leaf].bounds_max = box.max;
  for (uint32_t node = parents[leaf]; node != kNoParent; node = parents[node]) {
    __threadfence();
    if (atomicAdd(&arrivals[node], 1u) == 0) return;
    __threadfence();
    const uint32_t left = nodes[node].first;
    box = detail::merged(detail::load_node_box_from_l2(&nodes[left]), detail::load_node_box_from_l2(&nodes[left + 1]));
    nodes[node].bounds_min = box.min;
    nodes[node].bounds_max = box.max;
  }
}

// One thread per leaf counts the levels up to the root.
__global__ void depth_kernel(const accel::BvhNode* nodes, const uint32_t* parents, uint32_t node_count,
                             uint32_t* depth) {
  const uint32_t leaf = blockIdx.x * blockDim.x + threadIdx.x;
  if (leaf >= node_count || nodes[leaf].prim_count == 0) return;
  uint32_t levels = 1;
  for (uint32_t node = parents[leaf]; node != kNoParent; node = parents[node]) ++levels;
  atomicMax(depth, levels);
}

void check_parents(const GpuBvh& bvh, const char* what) {
  if (bvh.parents.size() != bvh.nodes.size())
    fail_message(std::string(what) + ": the BVH has " + std::to_string(bvh.parents.size()) + " parent links for " +
                 std::to_string(bvh.nodes.size()) + " nodes (upload it with GpuBvh::upload or build it on the GPU)");
}

}  // namespace

void refit_gpu(GpuBvh& bvh, const Aabb* prim_boxes, DeviceBuffer<uint32_t>& counters, cudaStream_t stream) {
  if (!bvh.refittable)
    fail_message("refit_gpu: this BVH is not refittable (its leaves hold split references); rebuild it instead");
  check_parents(bvh, "refit_gpu");
  const uint32_t node_count = bvh.node_count();
  if (node_count == 0) return;
  counters.resize(node_count);
  counters.fill_zero(stream);
  refit_kernel<<<detail::blocks_for(node_count), detail::kBlockSize, 0, stream>>>(
      bvh.nodes.data(), bvh.prim_indices.data(), bvh.parents.data(), prim_boxes, node_count, counters.data());
  GLINT_CUDA_CHECK_LAUNCH();
}

uint32_t measure_depth(const GpuBvh& bvh, cudaStream_t stream) {
  check_parents(bvh, "measure_depth");
  const uint32_t node_count = bvh.node_count();
  if (node_count == 0) return 0;
  DeviceBuffer<uint32_t> depth(1);
  depth.fill_zero(stream);
  depth_kernel<<<detail::blocks_for(node_count), detail::kBlockSize, 0, stream>>>(bvh.nodes.data(), bvh.parents.data(),
                                                                                  node_count, depth.data());
  GLINT_CUDA_CHECK_LAUNCH();
  uint32_t levels = 0;
  GLINT_CUDA_CHECK(cudaMemcpyAsync(&levels, depth.data(), sizeof(levels), cudaMemcpyDeviceToHost, stream));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
  return levels;
}

}  // namespace glint::cuda
