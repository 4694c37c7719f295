// The CUDA build path, exercised from day one: asks the runtime which GPUs exist. Every CUDA call is
// checked; "no GPU" is an ordinary answer (count 0), not an error.
#include "cuda/device_query.h"

#include <cuda_runtime.h>


namespace glint {

std::vector<CudaDeviceInfo> query_cuda_devices(std::string* why_none) {
  std::vector<CudaDeviceInfo> devices;
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess) {
    if (why_none) *why_none = std::string("no usable CUDA GPU: ") + cudaGetErrorString(status);
    cudaGetLastError();  // clear the sticky "no device" error so later calls start clean
    return devices;
  }
  for (int i = 0; i < count; ++i) {
    cudaDeviceProp properties{};
    if (cudaGetDeviceProperties(&properties, i) != cudaSuccess) continue;
    int driver_version = 0;
    cudaDriverGetVersion(&driver_version);
    devices.push_back({i, properties.name, properties.major * 10 + properties.minor,
                       static_cast<std::size_t>(properties.totalGlobalMem), driver_version});
  }
  if (devices.empty() && why_none) *why_none = "no CUDA device";
  return devices;
}

}  // namespace glint
