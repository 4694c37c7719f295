#pragma once
// The host-memory closest-hit and occlusion queries of the optix backends (RayTracer::trace_closest
// and trace_any, accel-bench):
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
#include <vector>

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

  // The occlusion query: occluded[i] = 1 when rays[i] hits anything within [t_min, t_max], else 0.
  // Same waiting, timing and errors as trace.
  double trace_any(TraceClosestPipeline& pipeline, OptixTraversableHandle root, std::span<const accel::Ray> rays,
                   std::span<std::uint8_t> occluded, cudaStream_t stream);

private:
  // Checks the sizes, uploads the rays and their count, and fills the launch parameters but the
  // outputs; false when there are no rays.
  bool stage(OptixTraversableHandle root, std::span<const accel::Ray> rays, std::size_t results,
             const char* result_name, OptixLaunchParams& params, cudaStream_t stream);
  // Launches between the timing events; returns the launch's GPU time after waiting for the stream.
  void timed_launch(TraceClosestPipeline& pipeline, const OptixLaunchParams& params, cudaStream_t stream);
  double wait_for_ms(cudaStream_t stream);

  cudaEvent_t start_ = nullptr;
  cudaEvent_t stop_ = nullptr;
  cuda::DeviceBuffer<accel::Ray> rays_;
  cuda::DeviceBuffer<accel::Hit> hits_;
  cuda::DeviceBuffer<std::uint32_t> count_;
  cuda::DeviceBuffer<std::uint32_t> occluded_;
  std::vector<std::uint32_t> occluded_download_;
};

}  // namespace glint::optix
