#pragma once
// Owning CUDA stream and event handles (created checked, destroyed unchecked in destructors), and the
// GPU time between two recorded events: what the cuda and optix backends and accel-bench's GPU rows
// time their work with. CUDA runtime header: include it from .cu files and src/optix/ only.
#include "cuda/cuda_check.h"

#include <cuda_runtime.h>

namespace glint::cuda {

class CudaStream {
public:
  // cudaStreamNonBlocking: the stream does not wait for the legacy default stream (callers that
  // copy on it synchronise themselves).
  explicit CudaStream(unsigned int flags = cudaStreamDefault) {
    GLINT_CUDA_CHECK(cudaStreamCreateWithFlags(&stream_, flags));
  }
  ~CudaStream() {
    cudaStreamSynchronize(stream_);  // work still queued may use buffers freed after the stream
    cudaStreamDestroy(stream_);
  }
  CudaStream(const CudaStream&) = delete;
  CudaStream& operator=(const CudaStream&) = delete;
  cudaStream_t get() const { return stream_; }

private:
  cudaStream_t stream_ = nullptr;
};

class CudaEvent {
public:
  CudaEvent() { GLINT_CUDA_CHECK(cudaEventCreate(&event_)); }
  ~CudaEvent() { cudaEventDestroy(event_); }
  CudaEvent(const CudaEvent&) = delete;
  CudaEvent& operator=(const CudaEvent&) = delete;
  void record(cudaStream_t stream) { GLINT_CUDA_CHECK(cudaEventRecord(event_, stream)); }
  cudaEvent_t get() const { return event_; }

private:
  cudaEvent_t event_ = nullptr;
};

// Milliseconds of GPU time from `start` to `end`, waiting for `end` to be reached.
inline double elapsed_ms(const CudaEvent& start, const CudaEvent& end) {
  GLINT_CUDA_CHECK(cudaEventSynchronize(end.get()));
  float ms = 0.0f;
  GLINT_CUDA_CHECK(cudaEventElapsedTime(&ms, start.get(), end.get()));
  return static_cast<double>(ms);
}

}  // namespace glint::cuda
