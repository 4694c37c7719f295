// A build without CUDA: the cuda backend is unavailable, said when it is asked for.
#include "cuda/cuda_ray_tracer.h"

#if !GLINT_HAVE_CUDA
#include "core/error.h"

namespace glint::cuda {

std::unique_ptr<rt::RayTracer> make_cuda_ray_tracer(const CudaTracerOptions&) {
  fail("--backend cuda: glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)");
}

}  // namespace glint::cuda
#endif
