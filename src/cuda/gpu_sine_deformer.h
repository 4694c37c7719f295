#pragma once
// One deformable mesh's sine deformer on the GPU: the rest pose, the index buffer and the CPU
// deformer's vertex -> triangles adjacency in device memory, and the kernels that pose it.
// CUDA-only header: include it from .cu files.
#include "cuda/device_buffer.h"
#include "cuda/gpu_scene_deformer.h"
#include "scene/sine_deformer.h"

namespace glint::cuda {

class GpuSineDeformer {
public:
  explicit GpuSineDeformer(const SineDeformer& deformer);

  // Poses the mesh at `time_seconds` on `stream`: positions into `positions` (vertex_count vec3,
  // device memory, may be null) and positions and normals into `gl_vertices` (vertex_count
  // entries, device memory, may be null; w components kept).
  void apply(float time_seconds, vec3* positions, DeformedGlVertex* gl_vertices, cudaStream_t stream);

  uint32_t vertex_count() const { return static_cast<uint32_t>(rest_.size()); }

private:
  SineDeform parameters_;
  DeviceBuffer<vec3> rest_;
  DeviceBuffer<uint32_t> indices_;
  DeviceBuffer<uint32_t> vertex_offsets_;    // vertex_count + 1
  DeviceBuffer<uint32_t> vertex_triangles_;  // ascending per vertex, like the CPU deformer's
  DeviceBuffer<vec3> posed_;                 // scratch: positions when the caller gives none
  DeviceBuffer<vec3> face_normals_;          // scratch, one per triangle
};

}  // namespace glint::cuda
