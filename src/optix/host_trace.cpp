#include "optix/host_trace.h"

#include "core/error.h"
#include "optix/ray_records.h"

#include <limits>

namespace glint::optix {

HostTraceStaging::HostTraceStaging() {
  GLINT_CUDA_CHECK(cudaEventCreate(&start_));
  GLINT_CUDA_CHECK(cudaEventCreate(&stop_));
}

HostTraceStaging::~HostTraceStaging() {
  cudaEventDestroy(start_);
  cudaEventDestroy(stop_);
}

double HostTraceStaging::trace(TraceClosestPipeline& pipeline, OptixTraversableHandle root,
                               std::span<const accel::Ray> rays, std::span<accel::Hit> hits, cudaStream_t stream) {
  if (rays.size() != hits.size()) fail("optix trace_closest: {} rays but {} hit records", rays.size(), hits.size());
  if (rays.size() > std::numeric_limits<std::uint32_t>::max())
    fail("optix trace_closest: {} rays exceed one launch's 2^32 - 1", rays.size());
  if (rays.empty()) return 0.0;
  const auto count = static_cast<std::uint32_t>(rays.size());
  rays_.upload(rays, stream);
  count_.upload(std::span<const std::uint32_t>(&count, 1), stream);
  hits_.resize(hits.size());
  OptixLaunchParams params;
  params.root = root;
  params.rays = as_ray_records(rays_.data());
  params.hits = as_hit_records(hits_.data());
  params.ray_count = count_.data();
  params.capacity = count;
  GLINT_CUDA_CHECK(cudaEventRecord(start_, stream));
  pipeline.launch(params, stream);
  GLINT_CUDA_CHECK(cudaEventRecord(stop_, stream));
  GLINT_CUDA_CHECK(cudaMemcpyAsync(hits.data(), hits_.data(), hits.size_bytes(), cudaMemcpyDeviceToHost, stream));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
  float ms = 0.0f;
  GLINT_CUDA_CHECK(cudaEventElapsedTime(&ms, start_, stop_));
  return ms;
}

}  // namespace glint::optix
