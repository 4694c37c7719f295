#pragma once
// The OptiX instance acceleration structure (IAS) over a scene's instances: one OptixInstance per
// scene instance, in scene order, so optixGetInstanceIndex is the scene's instance index. It is
// rebuilt from scratch at every update (tens of instances: far cheaper than any GAS work), into
// buffers kept from the first build. Needs the OptiX and CUDA headers.
#include "core/math.h"
#include "cuda/device_buffer.h"
#include "cuda/pinned_upload.h"

#include <cuda_runtime.h>
#include <optix_types.h>

#include <cstddef>
#include <span>
#include <vector>

namespace glint::optix {

// An instance record: object-to-world `transform` (glm, column-major) as OptiX's row-major 3x4,
// face culling and any-hit off, every visibility bit set.
OptixInstance make_instance(const mat4& transform, unsigned int index, OptixTraversableHandle gas);

class InstanceAccel {
public:
  // Uploads `instances` (asynchronously, from pinned memory) and builds the IAS over them on
  // `stream` with `build_flags`; `scratch` is grown when too small.
  void build(OptixDeviceContext context, std::span<const OptixInstance> instances, unsigned int build_flags,
             cuda::DeviceBuffer<std::byte>& scratch, cudaStream_t stream);

  OptixTraversableHandle handle() const { return handle_; }
  std::size_t bytes() const { return output_.size() + instances_.size() * sizeof(OptixInstance); }

private:
  cuda::PinnedUpload<OptixInstance> instances_;
  cuda::DeviceBuffer<std::byte> output_;
  OptixTraversableHandle handle_ = 0;
};

}  // namespace glint::optix
