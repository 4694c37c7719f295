#pragma once
// One OptiX geometry acceleration structure (GAS) over one triangle mesh, owning the mesh's device
// copy (positions, and indices unless the triangles are a gathered soup). Its output buffer is kept
// between builds and sized for the largest of the flag sets it will be built with, so rebuilding
// and updating it every frame allocate nothing. Needs the OptiX and CUDA headers.
#include "core/math.h"
#include "cuda/device_buffer.h"
#include "optix/build_preference.h"

#include <cuda_runtime.h>
#include <optix_types.h>

#include <cstddef>
#include <cstdint>
#include <span>

namespace glint::optix {

// The build flags of a GAS: the preference (fast trace or fast build), compaction (fast trace only,
// for GASes never rebuilt: compacting needs the host to wait for the compacted size) and
// ALLOW_UPDATE for GASes that will be updated in place.
unsigned int gas_build_flags(BuildPreference preference, bool compact, bool allow_update);

class TriangleGas {
public:
  // Copies the mesh to the device (synchronously): `indices` three per triangle, or empty when
  // `positions` are three per triangle. glint::Error for counts OptiX cannot take.
  void set_geometry(std::span<const vec3> positions, std::span<const std::uint32_t> indices);
  // Overwrites the positions (same count) on `stream`, asynchronously: `positions` must stay alive
  // and unchanged until the stream has run the copy.
  void upload_positions(std::span<const vec3> positions, cudaStream_t stream);
  vec3* device_positions() { return positions_.data(); }
  std::size_t vertex_count() const { return positions_.size(); }
  std::size_t triangle_count() const { return triangle_count_; }

  // Bytes a build with `flags` needs (output, temp, temp of an update).
  OptixAccelBufferSizes buffer_sizes(OptixDeviceContext context, unsigned int flags) const;
  // Makes the output buffer at least `bytes` large (allocates only when it grows).
  void reserve_output(std::size_t bytes);

  // Builds from scratch with `flags` into the kept output buffer, using `scratch` (grown if needed)
  // as temp memory, on `stream`. With `compacted_size` (a device pointer) the build also writes the
  // compacted size there (needs OPTIX_BUILD_FLAG_ALLOW_COMPACTION).
  void build(OptixDeviceContext context, unsigned int flags, cuda::DeviceBuffer<std::byte>& scratch,
             cudaStream_t stream, std::uint64_t* compacted_size = nullptr);
  // Refits the last build to the current positions (OPTIX_BUILD_OPERATION_UPDATE); glint::Error when
  // it was not built with OPTIX_BUILD_FLAG_ALLOW_UPDATE.
  void update(OptixDeviceContext context, cuda::DeviceBuffer<std::byte>& scratch, cudaStream_t stream);
  // Copies the built structure into a buffer of `compacted_bytes` (read from build's compacted_size)
  // and frees the larger one; waits for `stream`.
  void compact(OptixDeviceContext context, std::size_t compacted_bytes, cudaStream_t stream);

  OptixTraversableHandle handle() const { return handle_; }
  bool updatable() const;
  unsigned int flags() const { return flags_; }
  std::size_t structure_bytes() const { return output_.size(); }
  std::size_t geometry_bytes() const { return positions_.bytes() + indices_.bytes(); }

private:
  OptixBuildInput build_input() const;

  cuda::DeviceBuffer<vec3> positions_;
  cuda::DeviceBuffer<std::uint32_t> indices_;
  std::size_t triangle_count_ = 0;
  // OptixBuildInput points at these while a build is being set up.
  mutable CUdeviceptr vertex_pointer_ = 0;
  cuda::DeviceBuffer<std::byte> output_;
  OptixTraversableHandle handle_ = 0;
  unsigned int flags_ = 0;
  bool built_ = false;
};

}  // namespace glint::optix
