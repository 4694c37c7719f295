#include "cuda/gpu_bvh_sah.h"

#include "accel/builders/primitive_bounds.h"

namespace glint::cuda {
namespace {

constexpr uint32_t kBlock = 256;

// sums[0] += interior half areas, sums[1] += leaf half area x prims; one block-wide reduction, then
// one atomic per block.
__global__ void __launch_bounds__(kBlock) sah_sums_kernel(const accel::BvhNode* nodes, uint32_t count, double* sums) {
  __shared__ double interior[kBlock];
  __shared__ double leaves[kBlock];
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  double a = 0.0, b = 0.0;
  if (i < count) {
    const accel::BvhNode& node = nodes[i];
    const double area = accel::half_area(node.bounds());
    if (node.is_leaf())
      b = area * node.prim_count;
    else
      a = area;
  }
  interior[threadIdx.x] = a;
  leaves[threadIdx.x] = b;
  __syncthreads();
  for (uint32_t stride = kBlock / 2; stride > 0; stride /= 2) {
    if (threadIdx.x < stride) {
      interior[threadIdx.x] += interior[threadIdx.x + stride];
      leaves[threadIdx.x] += leaves[threadIdx.x + stride];
    }
    __syncthreads();
  }
  if (threadIdx.x == 0) {
    atomicAdd(&sums[0], interior[0]);
    atomicAdd(&sums[1], leaves[0]);
  }
}

__global__ void sah_finish_kernel(const accel::BvhNode* nodes, const double* sums, float node_cost, float prim_cost,
                                  float* cost) {
  const double root_area = accel::half_area(nodes[0].bounds());
  const double normaliser = root_area > 0.0 ? root_area : 1.0;
  *cost = static_cast<float>((node_cost * sums[0] + prim_cost * sums[1]) / normaliser);
}

}  // namespace

void compute_sah_gpu(const GpuBvh& bvh, const accel::SahCosts& costs, DeviceBuffer<double>& sums, float* cost,
                     cudaStream_t stream) {
  if (bvh.node_count() == 0) {
    GLINT_CUDA_CHECK(cudaMemsetAsync(cost, 0, sizeof(float), stream));
    return;
  }
  sums.resize(2);
  sums.fill_zero(stream);
  const uint32_t count = bvh.node_count();
  sah_sums_kernel<<<(count + kBlock - 1) / kBlock, kBlock, 0, stream>>>(bvh.nodes.data(), count, sums.data());
  GLINT_CUDA_CHECK_LAUNCH();
  sah_finish_kernel<<<1, 1, 0, stream>>>(bvh.nodes.data(), sums.data(), costs.node, costs.prim, cost);
  GLINT_CUDA_CHECK_LAUNCH();
}

}  // namespace glint::cuda
