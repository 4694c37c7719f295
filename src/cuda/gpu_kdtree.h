#pragma once
// A kd-tree in GPU memory, in exactly accel::KdNode's layout, so accel/kdtree/kdtree_traverse.h's host-device
// walk reads it unchanged: the cuda backend's BLAS for AccelOptions::blas = kdtree. Built on the CPU
// (accel::build_kdtree) and uploaded; it cannot be refitted (accel/kdtree/kdtree.h), so an update rebuilds it.
// CUDA-only header: include it from .cu files.
#include "accel/kdtree/kdtree.h"
#include "cuda/device_buffer.h"

#include <cstdint>
#include <span>

namespace glint::cuda {

struct GpuKdTree {
  DeviceBuffer<accel::KdNode> nodes;    // nodes[0] is the root
  DeviceBuffer<uint32_t> prim_indices;  // leaf references -> triangle index
  Aabb bounds;                          // the root cell
  uint32_t depth = 0;                   // levels, root = 1 (<= accel::kMaxKdDepth by construction)

  std::size_t memory_bytes() const { return nodes.bytes() + prim_indices.bytes(); }
  // Device pointers: valid on the GPU only.
  accel::KdTreeView view() const {
    return {nodes.data(), prim_indices.data(), static_cast<uint32_t>(nodes.size()), bounds};
  }
  // Copies a CPU-built tree asynchronously on `stream` (pageable memory is staged before
  // cudaMemcpyAsync returns, so `tree` may go as soon as this returns).
  void upload(const accel::KdTree& tree, cudaStream_t stream) {
    nodes.upload(std::span<const accel::KdNode>(tree.nodes), stream);
    prim_indices.upload(std::span<const uint32_t>(tree.prim_indices), stream);
    bounds = tree.bounds;
    depth = tree.depth;
  }
};

}  // namespace glint::cuda
