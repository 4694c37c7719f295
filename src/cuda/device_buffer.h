#pragma once
// DeviceBuffer<T>: an owning array in GPU memory (cudaMalloc/cudaFree, move-only). resize() keeps
// the allocation when it is large enough, so per-frame code that resizes to the same or a smaller
// size allocates nothing. CUDA-only header: include it from .cu files.
#include "cuda/cuda_check.h"

#include <cstddef>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace glint::cuda {

template <typename T>
class DeviceBuffer {
  static_assert(std::is_trivially_copyable_v<T>, "device buffers hold plain data");

public:
  DeviceBuffer() = default;
  explicit DeviceBuffer(std::size_t count) { resize(count); }
  ~DeviceBuffer() { release(); }
  DeviceBuffer(DeviceBuffer&& other) noexcept { swap(other); }
  DeviceBuffer& operator=(DeviceBuffer&& other) noexcept {
    if (this != &other) {
      release();
      swap(other);
    }
    return *this;
  }
  DeviceBuffer(const DeviceBuffer&) = delete;
  DeviceBuffer& operator=(const DeviceBuffer&) = delete;

  // Sets the element count; the contents are undefined after growing past the capacity.
  void resize(std::size_t count) {
    if (count > capacity_) {
      release();
      GLINT_CUDA_CHECK(cudaMalloc(reinterpret_cast<void**>(&data_), count * sizeof(T)));
      capacity_ = count;
    }
    size_ = count;
  }

  // Resizes to host.size() and copies (synchronously unless a stream is given).
  void upload(std::span<const T> host, cudaStream_t stream = nullptr) {
    resize(host.size());
    if (host.empty()) return;
    if (stream) {
      GLINT_CUDA_CHECK(cudaMemcpyAsync(data_, host.data(), host.size_bytes(), cudaMemcpyHostToDevice, stream));
    } else {
      GLINT_CUDA_CHECK(cudaMemcpy(data_, host.data(), host.size_bytes(), cudaMemcpyHostToDevice));
    }
  }

  // Synchronous copy of the whole buffer to the host.
  std::vector<T> download() const {
    std::vector<T> host(size_);
    if (size_ != 0) GLINT_CUDA_CHECK(cudaMemcpy(host.data(), data_, size_ * sizeof(T), cudaMemcpyDeviceToHost));
    return host;
  }

  void fill_zero(cudaStream_t stream = nullptr) {
    if (size_ != 0) GLINT_CUDA_CHECK(cudaMemsetAsync(data_, 0, size_ * sizeof(T), stream));
  }

  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }
  std::size_t bytes() const { return size_ * sizeof(T); }
  bool empty() const { return size_ == 0; }

private:
  void release() {
    if (data_) cudaFree(data_);  // not checked: runs in destructors, and a failed free leaks only
    data_ = nullptr;
    size_ = capacity_ = 0;
  }
  void swap(DeviceBuffer& other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
  }

  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace glint::cuda
