#pragma once
// The Morton order both GPU builders start from, computed without a host round trip: the bounds of
// the box centres reduced on the GPU, 30-bit codes of the centres in those bounds
// (accel/builders/morton_code.h, as the CPU builders quantise), sorted by CUB's radix sort with the
// primitive indices as values. CUDA-only header: include it from .cu files.
#include "cuda/device_buffer.h"
#include "core/math.h"

#include <cstddef>
#include <cstdint>

namespace glint::cuda::detail {

class MortonSort {
public:
  // Sorts primitives 0..count-1 (count >= 1) by the Morton code of their box centres on `stream`.
  // The sort is stable, so equal codes keep the primitives in index order: the order is that of the
  // unique 64-bit keys (code << 32 | index), which the LBVH's radix tree compares.
  void sort(const Aabb* boxes, uint32_t count, cudaStream_t stream);

  const uint32_t* sorted_codes() const { return sorted_codes_.data(); }
  const uint32_t* sorted_prims() const { return sorted_prims_.data(); }

private:
  DeviceBuffer<uint32_t> codes_, sorted_codes_, prims_, sorted_prims_;
  DeviceBuffer<uint32_t> bound_keys_;  // the centre bounds as order-preserving integers: min xyz, max xyz
  DeviceBuffer<unsigned char> sort_temp_;
};

}  // namespace glint::cuda::detail
