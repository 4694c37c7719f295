#include "cuda/gpu_sine_deformer.h"

#include "scene/sine_deform_math.h"

#include <string>

namespace glint::cuda {
namespace {

constexpr int kBlockSize = 256;

unsigned int blocks_for(uint32_t count) { return (count + kBlockSize - 1) / kBlockSize; }

__global__ void pose_positions(const vec3* rest, uint32_t vertex_count, SineDeform parameters, float phase, vec3* posed) {
  const uint32_t v = blockIdx.x * blockDim.x + threadIdx.x;
  if (v < vertex_count) posed[v] = sine_displaced(rest[v], parameters, phase);
}

__global__ void face_normals_kernel(const vec3* posed, const uint32_t* indices, uint32_t triangle_count, vec3* normals) {
  const uint32_t t = blockIdx.x * blockDim.x + threadIdx.x;
  if (t >= triangle_count) return;
  normals[t] = weighted_face_normal(posed[indices[3 * t]], posed[indices[3 * t + 1]], posed[indices[3 * t + 2]]);
}

// Gathers each vertex's face normals in the CPU deformer's order (ascending triangles), so the sums
// match it up to fused multiply-adds, and writes each vertex's position and normal.
__global__ void vertex_normals_kernel(const vec3* posed, const vec3* face_normals, const uint32_t* offsets,
                                      const uint32_t* triangles, uint32_t vertex_count, PosedVertex* vertices) {
  const uint32_t v = blockIdx.x * blockDim.x + threadIdx.x;
  if (v >= vertex_count) return;
  vec3 sum(0.0f);
  for (uint32_t k = offsets[v]; k < offsets[v + 1]; ++k) sum += face_normals[triangles[k]];
  const vec3 normal = smooth_normal_from_sum(sum);
  vertices[v] = PosedVertex{posed[v], normal};
}

}  // namespace

GpuSineDeformer::GpuSineDeformer(const SineDeformer& deformer)
    : mesh_name_(deformer.mesh_name()), parameters_(deformer.parameters()) {
  const std::vector<std::size_t>& offsets = deformer.vertex_offsets();
  if (!offsets.empty() && offsets.back() > 0xFFFFFFFFull)
    fail_message("mesh '" + deformer.mesh_name() + "': too many triangle corners for the GPU deformer");
  const std::vector<uint32_t> offsets32(offsets.begin(), offsets.end());
  rest_.upload(std::span<const vec3>(deformer.rest_positions()));
  indices_.upload(std::span<const uint32_t>(deformer.indices()));
  vertex_offsets_.upload(std::span<const uint32_t>(offsets32));
  vertex_triangles_.upload(std::span<const uint32_t>(deformer.vertex_triangles()));
}

void GpuSineDeformer::apply(float time_seconds, vec3* positions, cudaStream_t stream) {
  const uint32_t vertex_count = this->vertex_count();
  if (vertex_count == 0) return;
  require_device_memory(positions, "positions");
  pose_positions<<<blocks_for(vertex_count), kBlockSize, 0, stream>>>(rest_.data(), vertex_count, parameters_,
                                                                      parameters_.speed * time_seconds, positions);
  GLINT_CUDA_CHECK_LAUNCH();
}

void GpuSineDeformer::apply_with_normals(float time_seconds, vec3* positions, PosedVertex* vertices,
                                         cudaStream_t stream) {
  const uint32_t vertex_count = this->vertex_count();
  const auto triangle_count = static_cast<uint32_t>(indices_.size() / 3);
  if (vertex_count == 0) return;
  require_device_memory(vertices, "vertices");
  apply(time_seconds, positions, stream);
  face_normals_.resize(triangle_count);  // allocates once: the same size on every later call
  if (triangle_count != 0) {
    face_normals_kernel<<<blocks_for(triangle_count), kBlockSize, 0, stream>>>(positions, indices_.data(),
                                                                              triangle_count, face_normals_.data());
    GLINT_CUDA_CHECK_LAUNCH();
  }
  vertex_normals_kernel<<<blocks_for(vertex_count), kBlockSize, 0, stream>>>(
      positions, face_normals_.data(), vertex_offsets_.data(), vertex_triangles_.data(), vertex_count, vertices);
  GLINT_CUDA_CHECK_LAUNCH();
}

void GpuSineDeformer::require_device_memory(const void* pointer, const char* what) const {
  if (pointer == nullptr)
    fail_message("mesh '" + mesh_name_ + "': the GPU deformer was given no device memory for its " + what);
}

}  // namespace glint::cuda
