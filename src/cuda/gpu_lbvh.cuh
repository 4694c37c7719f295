#pragma once
// LBVH on the GPU (Karras 2012): Morton order, one thread per interior node of the radix tree over
// the unique keys, boxes bottom-up with atomic arrival counters, then the flat layout.
// CUDA-only header: include it from .cu files.
#include "cuda/gpu_bvh.h"
#include "cuda/gpu_bvh_layout.cuh"
#include "cuda/gpu_morton.cuh"

namespace glint::cuda::detail {

struct LbvhScratch {
  MortonSort morton;
  BuildTree tree;
  DeviceBuffer<uint32_t> arrivals;  // per interior node, for the bottom-up box pass
};

// Builds `out` over prim_boxes[0, count), count >= 1; `out`'s arrays must be sized already
// (2 count - 1 nodes and parents, count prim_indices).
void build_lbvh_gpu(const Aabb* prim_boxes, uint32_t count, LbvhScratch& scratch, GpuBvh& out, cudaStream_t stream);

// The tree's depth never exceeds this: every level of a radix tree over distinct keys lengthens the
// common prefix by at least one bit, the keys differ only in the 30 code bits and the 31 bits of a
// primitive index (< 2^31), so there are at most 61 interior levels and a leaf level below them.
inline constexpr uint32_t kLbvhDepthBound = 62;

}  // namespace glint::cuda::detail
