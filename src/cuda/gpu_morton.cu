#include "cuda/gpu_morton.cuh"

#include "accel/builders/morton_code.h"
#include "cuda/gpu_bvh_layout.cuh"

#include <cub/cub.cuh>

namespace glint::cuda::detail {
namespace {

// Floats as unsigned integers in the same order (negative values flipped, positive ones with the
// sign bit set), so the bounds reduce with integer atomicMin/atomicMax, which are exact and
// independent of the order threads arrive in.
__device__ inline uint32_t ordered_key(float value) {
  const uint32_t bits = __float_as_uint(value);
  return (bits & 0x80000000u) ? ~bits : (bits | 0x80000000u);
}

__device__ inline float key_value(uint32_t key) {
  return __uint_as_float((key & 0x80000000u) ? (key & 0x7FFFFFFFu) : ~key);
}

struct MergeBoxes {
  __device__ Aabb operator()(const Aabb& a, const Aabb& b) const { return merged(a, b); }
};

// Each block reduces its share of the centres (grid-stride), then one thread folds the block's box
// into the six keys. bound_keys must start as min = 0xFFFFFFFF, max = 0.
__global__ void centre_bounds_kernel(const Aabb* boxes, uint32_t count, uint32_t* bound_keys) {
  using BlockReduce = cub::BlockReduce<Aabb, kBlockSize>;
  __shared__ typename BlockReduce::TempStorage temp;
  Aabb mine;
  for (uint32_t i = blockIdx.x * blockDim.x + threadIdx.x; i < count; i += gridDim.x * blockDim.x)
    mine.extend(boxes[i].center());
  const Aabb block = BlockReduce(temp).Reduce(mine, MergeBoxes{});
  if (threadIdx.x != 0) return;
  for (int axis = 0; axis < 3; ++axis) {
    atomicMin(&bound_keys[axis], ordered_key(block.min[axis]));
    atomicMax(&bound_keys[3 + axis], ordered_key(block.max[axis]));
  }
}

__global__ void morton_codes_kernel(const Aabb* boxes, uint32_t count, const uint32_t* bound_keys, uint32_t* codes,
                                    uint32_t* prims) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= count) return;
  const vec3 origin(key_value(bound_keys[0]), key_value(bound_keys[1]), key_value(bound_keys[2]));
  const vec3 top(key_value(bound_keys[3]), key_value(bound_keys[4]), key_value(bound_keys[5]));
  const vec3 scale = accel::unit_cube_scale(top - origin);
  codes[i] = accel::morton30((boxes[i].center() - origin) * scale);
  prims[i] = i;
}

}  // namespace

void MortonSort::sort(const Aabb* boxes, uint32_t count, cudaStream_t stream) {
  codes_.resize(count);
  sorted_codes_.resize(count);
  prims_.resize(count);
  sorted_prims_.resize(count);
  bound_keys_.resize(6);
  GLINT_CUDA_CHECK(cudaMemsetAsync(bound_keys_.data(), 0xFF, 3 * sizeof(uint32_t), stream));
  GLINT_CUDA_CHECK(cudaMemsetAsync(bound_keys_.data() + 3, 0x00, 3 * sizeof(uint32_t), stream));
  // A few blocks per SM are plenty for a memory-bound reduction; the grid-stride loop covers the rest.
  const unsigned int reduce_blocks = blocks_for(count) < 1024u ? blocks_for(count) : 1024u;
  centre_bounds_kernel<<<reduce_blocks, kBlockSize, 0, stream>>>(boxes, count, bound_keys_.data());
  GLINT_CUDA_CHECK_LAUNCH();
  morton_codes_kernel<<<blocks_for(count), kBlockSize, 0, stream>>>(boxes, count, bound_keys_.data(), codes_.data(),
                                                                    prims_.data());
  GLINT_CUDA_CHECK_LAUNCH();

  // 30-bit codes with the indices as values: 4 radix passes over 8 bytes per primitive instead of
  // 8 passes over 64-bit keys, and the same order (the sort is stable).
  constexpr int kCodeBits = 30;
  std::size_t temp_bytes = 0;
  GLINT_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(nullptr, temp_bytes, codes_.data(), sorted_codes_.data(),
                                                   prims_.data(), sorted_prims_.data(), count, 0, kCodeBits, stream));
  sort_temp_.resize(temp_bytes);  // keeps its allocation once large enough
  GLINT_CUDA_CHECK(cub::DeviceRadixSort::SortPairs(sort_temp_.data(), temp_bytes, codes_.data(), sorted_codes_.data(),
                                                   prims_.data(), sorted_prims_.data(), count, 0, kCodeBits, stream));
}

}  // namespace glint::cuda::detail
