#pragma once
// One deformable mesh's sine deformer on the GPU: the rest pose, the index buffer and the CPU
// deformer's vertex -> triangles adjacency in device memory, and the kernels that pose it.
// CUDA-only header: include it from .cu files.
#include "core/math.h"
#include "cuda/device_buffer.h"
#include "scene/sine_deformer.h"

#include <string>

namespace glint::cuda {

// One vertex as apply_with_normals() poses it: its position and smooth unit normal. Only
// pose_mesh_on_gpu (cuda/gpu_scene_deformer.h, for tests) asks for normals; the frame path poses
// positions alone.
struct PosedVertex {
  vec3 position;
  vec3 normal;
};

class GpuSineDeformer {
public:
  explicit GpuSineDeformer(const SineDeformer& deformer);

  // Poses the mesh's positions at `time_seconds` into `positions` (vertex_count vec3 of device
  // memory; null only for a mesh without vertices, glint::Error otherwise), on `stream`. The frame
  // path's call: it needs no scratch memory.
  void apply(float time_seconds, vec3* positions, cudaStream_t stream);
  // apply(), then each vertex's smooth normal, written with its position into `vertices`
  // (vertex_count entries of device memory, same null rule). Its per-triangle scratch is allocated
  // on the first call, so only pose_mesh_on_gpu (tests) pays for it.
  void apply_with_normals(float time_seconds, vec3* positions, PosedVertex* vertices, cudaStream_t stream);

  uint32_t vertex_count() const { return static_cast<uint32_t>(rest_.size()); }

private:
  void require_device_memory(const void* pointer, const char* what) const;

  std::string mesh_name_;  // for error messages
  SineDeform parameters_;
  DeviceBuffer<vec3> rest_;
  DeviceBuffer<uint32_t> indices_;
  DeviceBuffer<uint32_t> vertex_offsets_;    // vertex_count + 1
  DeviceBuffer<uint32_t> vertex_triangles_;  // ascending per vertex, like the CPU deformer's
  DeviceBuffer<vec3> face_normals_;          // apply_with_normals' scratch, one per triangle
};

}  // namespace glint::cuda
