#pragma once
// A triangle mesh in GPU memory: positions and the index buffer, viewed as the accel::TriangleMesh
// that device traversal, builders and refit read. CUDA-only header: include it from .cu files.
#include "accel/triangle_mesh.h"
#include "cuda/device_buffer.h"

namespace glint::cuda {

struct GpuMesh {
  DeviceBuffer<vec3> positions;
  DeviceBuffer<uint32_t> indices;  // 3 per triangle

  // Copies `mesh` (indexed or soup; a soup gets no index buffer), synchronously unless a stream is given.
  void upload(const accel::TriangleMesh& mesh, cudaStream_t stream = nullptr);

  uint32_t vertex_count() const { return static_cast<uint32_t>(positions.size()); }
  uint32_t triangle_count() const {
    return static_cast<uint32_t>(indices.empty() ? positions.size() / 3 : indices.size() / 3);
  }
  // Device pointers: valid on the GPU only.
  accel::TriangleMesh view() const {
    return {positions.data(), indices.empty() ? nullptr : indices.data(), vertex_count(), triangle_count()};
  }
};

}  // namespace glint::cuda
