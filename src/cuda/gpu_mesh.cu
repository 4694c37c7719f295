#include "cuda/gpu_mesh.h"

namespace glint::cuda {

void GpuMesh::upload(const accel::TriangleMesh& mesh, cudaStream_t stream) {
  const std::size_t position_count = mesh.indices ? mesh.vertex_count : 3 * static_cast<std::size_t>(mesh.triangle_count);
  positions.upload(std::span<const vec3>(mesh.positions, position_count), stream);
  if (mesh.indices) {
    indices.upload(std::span<const uint32_t>(mesh.indices, 3 * static_cast<std::size_t>(mesh.triangle_count)), stream);
  } else {
    indices.resize(0);
  }
}

}  // namespace glint::cuda
