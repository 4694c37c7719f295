#pragma once
// Copies between host vectors and device memory for the CUDA tests that drive the device-side
// queries themselves (the renderer's path: rays and results already on the GPU). Failures are test
// failures, not exceptions: the test goes on and reports what else differs.
#if GLINT_HAVE_CUDA
#include <cuda_runtime.h>
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

namespace glint::testing {

// A cudaMalloc'ed copy of `host`; the caller cudaFree's it.
template <typename T>
T* device_copy(const std::vector<T>& host) {
  T* device = nullptr;
  EXPECT_EQ(cudaMalloc(reinterpret_cast<void**>(&device), host.size() * sizeof(T)), cudaSuccess);
  EXPECT_EQ(cudaMemcpy(device, host.data(), host.size() * sizeof(T), cudaMemcpyHostToDevice), cudaSuccess);
  return device;
}

template <typename T>
std::vector<T> host_copy(const T* device, std::size_t count) {
  std::vector<T> host(count);
  EXPECT_EQ(cudaMemcpy(host.data(), device, count * sizeof(T), cudaMemcpyDeviceToHost), cudaSuccess);
  return host;
}

}  // namespace glint::testing
#endif
