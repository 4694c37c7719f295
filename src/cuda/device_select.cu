#include "cuda/device_select.h"

#include "cuda/cuda_check.h"

#include <cuda_runtime.h>

namespace glint::cuda {

void use_device(int ordinal) { GLINT_CUDA_CHECK(cudaSetDevice(ordinal)); }

int visible_device_count() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess) {
    (void)cudaGetLastError();  // the error is the answer (no driver, no GPU), not a sticky state
    return 0;
  }
  return count;
}

}  // namespace glint::cuda
