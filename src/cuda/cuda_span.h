#pragma once
// The Span of GpuSpanPool (cuda/gpu_span_pool.h) for CUDA work: a start and a stop event recorded
// on the work's stream around it. CUDA runtime header: include it from .cu files and src/optix/ only.
#include "cuda/cuda_stream_events.h"

#include <cstdint>
#include <optional>

namespace glint::cuda {

struct CudaSpan {
  CudaEvent start, stop;

  // Milliseconds from start to stop; nullopt while the GPU has not reached the stop and `wait` is false.
  std::optional<double> elapsed_ms(bool wait) const {
    if (!wait) {
      const cudaError_t status = cudaEventQuery(stop.get());
      if (status == cudaErrorNotReady) {
        cudaGetLastError();  // a not-ready query is not an error; clear it
        return std::nullopt;
      }
      GLINT_CUDA_CHECK(status);
    }
    return cuda::elapsed_ms(start, stop);
  }
};

// Opens a span of `pool` (a GpuSpanPool or TracerGpuTimes of a CudaSpan kind) and records its start
// on `stream`; stop_span records its end.
template <typename Pool>
std::uint64_t start_span(Pool& pool, cudaStream_t stream) {
  const std::uint64_t ticket = pool.open();
  pool.span(ticket).start.record(stream);
  return ticket;
}
template <typename Pool>
void stop_span(Pool& pool, std::uint64_t ticket, cudaStream_t stream) {
  pool.span(ticket).stop.record(stream);
}

}  // namespace glint::cuda
