#include "cuda/trace_kernel.h"

namespace glint::cuda {

std::string_view trace_kernel_name(TraceKernel kernel) {
  return kernel == TraceKernel::persistent ? "persistent" : "one-ray-per-thread";
}

}  // namespace glint::cuda
