// Presence checks on top of query_cuda_devices, shared by builds with and without CUDA.
#include "cuda/device_query.h"

#include "core/error.h"

namespace glint {

bool cuda_gpu_present() { return !query_cuda_devices().empty(); }

void require_cuda_gpu(const char* what) {
  std::string why;
  if (query_cuda_devices(&why).empty()) fail("{} needs a CUDA GPU: {}", what, why);
}

}  // namespace glint
