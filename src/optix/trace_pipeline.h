#pragma once
// The OptiX pipeline of the closest-hit and occlusion queries: the embedded module
// trace_closest_programs (raygen, closest hit, miss; src/optix/device/), its program groups, the
// shader binding table (one record each, no data: every instance and triangle uses the one hit group)
// and the launch. The query is chosen by the launch parameters (OptixLaunchParams::occluded).
// Needs the OptiX and CUDA headers.
#include "optix/launch_params.h"
#include "cuda/pinned_upload.h"

#include <cuda_runtime.h>
#include <optix_types.h>

#include <cstddef>
#include <cstdint>

namespace glint::optix {

class TraceClosestPipeline {
public:
  // `validation`: the context's validation mode (turns on OptiX's exception checks in the programs).
  TraceClosestPipeline(OptixDeviceContext context, bool validation);
  ~TraceClosestPipeline();
  TraceClosestPipeline(const TraceClosestPipeline&) = delete;
  TraceClosestPipeline& operator=(const TraceClosestPipeline&) = delete;

  // Enqueues params.capacity raygen threads on `stream` (nothing when it is 0); returns at once.
  void launch(const OptixLaunchParams& params, cudaStream_t stream);

private:
  // One parameter block per query (closest hit, occlusion), so a frame that traces both does not
  // re-upload them (nor wait for the pinned staging of the other's upload) at every launch.
  struct ParamsSlot {
    cuda::PinnedUpload<OptixLaunchParams> device;
    OptixLaunchParams last{};
    bool uploaded = false;
  };

  OptixModule module_ = nullptr;
  OptixProgramGroup raygen_ = nullptr;
  OptixProgramGroup miss_ = nullptr;
  OptixProgramGroup hit_group_ = nullptr;
  OptixPipeline pipeline_ = nullptr;
  cuda::DeviceBuffer<std::byte> sbt_records_;
  OptixShaderBindingTable sbt_{};
  ParamsSlot params_[2];
};

}  // namespace glint::optix
