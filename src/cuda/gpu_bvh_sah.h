#pragma once
// The SAH cost of a BVH in device memory, computed on the GPU with accel::compute_stats' formula
// (Aila, Karras, Laine 2013: (C_node * sum of interior half areas + C_prim * sum of leaf half
// areas x prims) / root half area), so the CUDA backend's automatic update policy can watch a
// refitted structure's quality without downloading it. CUDA-only header: include it from .cu files.
#include "accel/bvh_stats.h"
#include "cuda/device_buffer.h"
#include "cuda/gpu_bvh.h"

namespace glint::cuda {

// Writes the cost to *cost (device memory) on `stream`; `sums` is scratch (resized, reused).
// An empty BVH costs 0.
void compute_sah_gpu(const GpuBvh& bvh, const accel::SahCosts& costs, DeviceBuffer<double>& sums, float* cost,
                     cudaStream_t stream);

}  // namespace glint::cuda
