// The answer of a build without CUDA: no devices, and why.
#include "cuda/device_query.h"

#if !GLINT_HAVE_CUDA
namespace glint {

std::vector<CudaDeviceInfo> query_cuda_devices(std::string* why_none) {
  if (why_none) *why_none = "glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)";
  return {};
}

}  // namespace glint
#endif
