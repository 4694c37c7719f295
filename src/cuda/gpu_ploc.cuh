#pragma once
// PLOC on the GPU (Meister & Bittner 2018): Morton-ordered clusters; each iteration finds every
// cluster's nearest neighbour within a radius, merges mutual pairs and compacts with a prefix sum,
// until one cluster remains; then the flat layout. CUDA-only header: include it from .cu files.
#include "cuda/gpu_bvh.h"
#include "cuda/gpu_bvh_layout.cuh"
#include "cuda/gpu_morton.cuh"

#include <cstdint>

namespace glint::cuda::detail {

// One cluster of an iteration: its tree node, box and height (levels, a leaf is 1).
struct PlocCluster {
  Aabb box;
  uint32_t node = 0;
  uint32_t height = 1;
};

// What the host reads back after each iteration.
struct PlocProgress {
  uint32_t cluster_count = 0;
  uint32_t max_height = 0;  // of every node merged so far
};

class PlocScratch {
public:
  PlocScratch() = default;
  ~PlocScratch();
  PlocScratch(const PlocScratch&) = delete;
  PlocScratch& operator=(const PlocScratch&) = delete;

  MortonSort morton;
  BuildTree tree;
  DeviceBuffer<PlocCluster> clusters[2];  // this iteration's and the next one's
  DeviceBuffer<uint32_t> nearest;         // per cluster: its nearest neighbour's position, or none
  DeviceBuffer<uint64_t> merge_flags;     // per cluster: (starts a merge) << 32 | (survives)
  DeviceBuffer<uint64_t> merge_offsets;   // their exclusive prefix sum
  DeviceBuffer<unsigned char> scan_temp;
  DeviceBuffer<PlocProgress> progress;
  PlocProgress* host_progress = nullptr;  // pinned, so the per-iteration read back is a short DMA
};

// Builds `out` over prim_boxes[0, count), count >= 1, with the neighbour search `radius` (>= 1)
// positions to each side; `out`'s arrays must be sized already (2 count - 1 nodes and parents,
// count prim_indices). The tree's depth is at most accel::kMaxBvhDepth (see the loop).
void build_ploc_gpu(const Aabb* prim_boxes, uint32_t count, uint32_t radius, PlocScratch& scratch, GpuBvh& out,
                    cudaStream_t stream);

}  // namespace glint::cuda::detail
