#pragma once
// A binary BVH in GPU memory, in exactly accel::BvhNode's layout (so the host-device traversal of
// accel/traverse.h walks it unchanged), plus each node's parent for bottom-up refit on the GPU.
// CPU-built structures of the menu arrive through upload(); GPU builders (gpu_bvh_build.h) write one
// directly. CUDA-only header: include it from .cu files.
#include "accel/bvh.h"
#include "cuda/device_buffer.h"

#include <cstdint>

namespace glint::cuda {

inline constexpr uint32_t kNoParent = 0xFFFFFFFFu;

struct GpuBvh {
  DeviceBuffer<accel::BvhNode> nodes;   // nodes[0] is the root
  DeviceBuffer<uint32_t> prim_indices;  // leaf slots -> primitive index
  DeviceBuffer<uint32_t> parents;       // parents[i] = parent of node i; kNoParent for the root
  uint32_t depth = 0;                   // levels, root = 1; traversal needs <= accel::kMaxBvhDepth
  bool refittable = true;               // false for split references (sbvh)

  uint32_t node_count() const { return static_cast<uint32_t>(nodes.size()); }
  std::size_t memory_bytes() const { return nodes.bytes() + prim_indices.bytes() + parents.bytes(); }
  // Device pointers: valid on the GPU only.
  accel::BvhView view() const { return {nodes.data(), prim_indices.data(), node_count()}; }

  // Copies a CPU-built BVH and its parent links (computed on the host), synchronously unless a
  // stream is given (then asynchronously on it: pageable host memory is staged before
  // cudaMemcpyAsync returns, so `bvh` may go as soon as this returns).
  void upload(const accel::Bvh& bvh, cudaStream_t stream = nullptr);
  // Copies the structure back (for tests and statistics); `builder` names it.
  accel::Bvh download(const char* builder) const;
};

// parents[i] for every node of a flat BVH (children found through BvhNode::left()/right()).
std::vector<uint32_t> bvh_parents(const accel::Bvh& bvh);

}  // namespace glint::cuda
