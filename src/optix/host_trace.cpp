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

bool HostTraceStaging::stage(OptixTraversableHandle root, std::span<const accel::Ray> rays, std::size_t results,
                             const char* result_name, OptixLaunchParams& params, cudaStream_t stream) {
  if (rays.size() != results) fail("optix trace: {} rays but {} {}", rays.size(), results, result_name);
  if (rays.size() > std::numeric_limits<std::uint32_t>::max())
    fail("optix trace: {} rays exceed one launch's 2^32 - 1", rays.size());
  if (rays.empty()) return false;
  const auto count = static_cast<std::uint32_t>(rays.size());
  rays_.upload(rays, stream);
  count_.upload(std::span<const std::uint32_t>(&count, 1), stream);
  params.root = root;
  params.rays = as_ray_records(rays_.data());
  params.ray_count = count_.data();
  params.capacity = count;
  return true;
}

void HostTraceStaging::timed_launch(TraceClosestPipeline& pipeline, const OptixLaunchParams& params,
                                    cudaStream_t stream) {
  GLINT_CUDA_CHECK(cudaEventRecord(start_, stream));
  pipeline.launch(params, stream);
  GLINT_CUDA_CHECK(cudaEventRecord(stop_, stream));
}

double HostTraceStaging::wait_for_ms(cudaStream_t stream) {
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
  float ms = 0.0f;
  GLINT_CUDA_CHECK(cudaEventElapsedTime(&ms, start_, stop_));
  return ms;
}

double HostTraceStaging::trace(TraceClosestPipeline& pipeline, OptixTraversableHandle root,
                               std::span<const accel::Ray> rays, std::span<accel::Hit> hits, cudaStream_t stream) {
  OptixLaunchParams params;
  if (!stage(root, rays, hits.size(), "hit records", params, stream)) return 0.0;
  hits_.resize(hits.size());
  params.hits = as_hit_records(hits_.data());
  timed_launch(pipeline, params, stream);
  GLINT_CUDA_CHECK(cudaMemcpyAsync(hits.data(), hits_.data(), hits.size_bytes(), cudaMemcpyDeviceToHost, stream));
  return wait_for_ms(stream);
}

double HostTraceStaging::trace_any(TraceClosestPipeline& pipeline, OptixTraversableHandle root,
                                   std::span<const accel::Ray> rays, std::span<std::uint8_t> occluded,
                                   cudaStream_t stream) {
  OptixLaunchParams params;
  if (!stage(root, rays, occluded.size(), "occlusion results", params, stream)) return 0.0;
  occluded_.resize(occluded.size());
  occluded_download_.resize(occluded.size());
  params.occluded = occluded_.data();
  timed_launch(pipeline, params, stream);
  GLINT_CUDA_CHECK(cudaMemcpyAsync(occluded_download_.data(), occluded_.data(),
                                   occluded_download_.size() * sizeof(std::uint32_t), cudaMemcpyDeviceToHost, stream));
  const double ms = wait_for_ms(stream);
  // The device writes one uint32_t per ray (what GLSL reads); the host interface has one byte.
  for (std::size_t i = 0; i < occluded.size(); ++i) occluded[i] = occluded_download_[i] != 0 ? 1 : 0;
  return ms;
}

}  // namespace glint::optix
