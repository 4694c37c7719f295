#pragma once
// A small host -> device upload that never makes the host wait for the GPU in the common case: the
// source is pinned host memory (a pageable source may make cudaMemcpyAsync wait for the stream),
// and it is overwritten only after the previous copy ran (an event; by then usually long done).
// Used for the launch parameters and the instance array, which change between frames at most.
// CUDA runtime header: include it from .cu files and src/optix/ only.
#include "cuda/cuda_check.h"
#include "cuda/device_buffer.h"

#include <cuda_runtime.h>

#include <cstddef>
#include <cstring>
#include <span>
#include <type_traits>

namespace glint::cuda {

template <typename T>
class PinnedUpload {
  static_assert(std::is_trivially_copyable_v<T>);

public:
  PinnedUpload() = default;
  ~PinnedUpload() { release(); }
  PinnedUpload(const PinnedUpload&) = delete;
  PinnedUpload& operator=(const PinnedUpload&) = delete;

  // Copies `values` to device() on `stream` (asynchronously). Allocates only when `values` is
  // larger than every earlier upload.
  void upload(std::span<const T> values, cudaStream_t stream) {
    if (values.size() > capacity_) {
      release();
      GLINT_CUDA_CHECK(cudaMallocHost(reinterpret_cast<void**>(&host_), values.size() * sizeof(T)));
      GLINT_CUDA_CHECK(cudaEventCreateWithFlags(&copied_, cudaEventDisableTiming));
      capacity_ = values.size();
    } else if (pending_) {
      GLINT_CUDA_CHECK(cudaEventSynchronize(copied_));
    }
    device_.resize(values.size());
    if (values.empty()) return;
    std::memcpy(host_, values.data(), values.size_bytes());
    GLINT_CUDA_CHECK(cudaMemcpyAsync(device_.data(), host_, values.size_bytes(), cudaMemcpyHostToDevice, stream));
    GLINT_CUDA_CHECK(cudaEventRecord(copied_, stream));
    pending_ = true;
  }

  const T* device() const { return device_.data(); }
  std::size_t size() const { return device_.size(); }

private:
  void release() {
    // Not checked: runs in destructors. A pending copy must finish before its source is freed.
    if (copied_) {
      cudaEventSynchronize(copied_);
      cudaEventDestroy(copied_);
    }
    if (host_) cudaFreeHost(host_);
    host_ = nullptr;
    copied_ = nullptr;
    capacity_ = 0;
    pending_ = false;
  }

  T* host_ = nullptr;
  std::size_t capacity_ = 0;
  cudaEvent_t copied_ = nullptr;
  bool pending_ = false;
  cuda::DeviceBuffer<T> device_;
};

}  // namespace glint::cuda
