#pragma once
// The host-memory closest-hit query of the optix backends (RayTracer::trace_closest, accel-bench):
// the rays are uploaded, traced by the pipeline over `root`, and the hits downloaded. The device
// buffers are kept, so repeated traces of the same size allocate nothing. The launch alone is timed
// (accel-bench's optix rows report it, like the cuda rows' kernel time). Needs the CUDA headers.
#include "accel/ray.h"
#include "cuda/device_buffer.h"
#include "optix/trace_pipeline.h"

#include <cuda_runtime.h>
#include <optix_types.h>

#include <cstdint>
#include <span>

namespace glint::optix {

class HostTraceStaging {
public:
  HostTraceStaging();
  ~HostTraceStaging();
  HostTraceStaging(const HostTraceStaging&) = delete;
  HostTraceStaging& operator=(const HostTraceStaging&) = delete;

  // hits[i] = closest hit of rays[i]; waits for the GPU and returns the launch's GPU time in ms (CUDA
  // events; uploads and the download excluded). glint::Error when the spans differ in size or hold
  // more than 2^32 - 1 rays.
  double trace(TraceClosestPipeline& pipeline, OptixTraversableHandle root, std::span<const accel::Ray> rays,
               std::span<accel::Hit> hits, cudaStream_t stream);

private:
  cudaEvent_t start_ = nullptr;
  cudaEvent_t stop_ = nullptr;
  cuda::DeviceBuffer<accel::Ray> rays_;
  cuda::DeviceBuffer<accel::Hit> hits_;
  cuda::DeviceBuffer<std::uint32_t> count_;
};

}  // namespace glint::optix
