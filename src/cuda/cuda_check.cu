#include "cuda/cuda_check.h"

#include "core/error.h"

#include <cstring>

namespace glint::cuda {

void throw_cuda_error(cudaError_t status, const char* call, const char* file, int line) {
  // Only the file's name: the build directory's absolute path says nothing to a user.
  const char* slash = std::strrchr(file, '/');
  cudaGetLastError();  // clear a non-sticky error so the caller may go on after catching
  fail("CUDA error {} ({}) in {} at {}:{}", cudaGetErrorName(status), cudaGetErrorString(status), call,
       slash ? slash + 1 : file, line);
}

}  // namespace glint::cuda
