#pragma once
// Every CUDA runtime call and kernel launch goes through GLINT_CUDA_CHECK, so a failure becomes one
// glint::Error naming the call, the file and the line, and the CLI prints it like any other error.
// CUDA-only header: include it from .cu files.
#include "cuda/cuda_errors.h"

#include <cuda_runtime.h>

#define GLINT_CUDA_CHECK(call)                                                                            \
  do {                                                                                                    \
    const cudaError_t glint_cuda_status_ = (call);                                                        \
    if (glint_cuda_status_ != cudaSuccess) {                                                              \
      cudaGetLastError(); /* clear a non-sticky error so a caller that catches may go on */              \
      ::glint::cuda::throw_cuda_error(cudaGetErrorName(glint_cuda_status_),                               \
                                      cudaGetErrorString(glint_cuda_status_), #call, __FILE__, __LINE__); \
    }                                                                                                     \
  } while (0)

// After a kernel launch: reports launch-configuration errors at once (execution errors surface at
// the next synchronising call, which is checked too).
#define GLINT_CUDA_CHECK_LAUNCH() GLINT_CUDA_CHECK(cudaGetLastError())
