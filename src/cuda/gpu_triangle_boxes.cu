#include "cuda/gpu_bvh_build.h"

#include "cuda/gpu_bvh_layout.cuh"

namespace glint::cuda {
namespace {

__global__ void triangle_boxes_kernel(accel::TriangleMesh mesh, Aabb* boxes) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i < mesh.triangle_count) boxes[i] = mesh.triangle(i).bounds();
}

}  // namespace

void compute_triangle_boxes(const accel::TriangleMesh& device_mesh, Aabb* boxes, cudaStream_t stream) {
  if (device_mesh.triangle_count == 0) return;
  triangle_boxes_kernel<<<detail::blocks_for(device_mesh.triangle_count), detail::kBlockSize, 0, stream>>>(device_mesh,
                                                                                                         boxes);
  GLINT_CUDA_CHECK_LAUNCH();
}

}  // namespace glint::cuda
