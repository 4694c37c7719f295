// A build without CUDA: the GPU builders are unavailable, said by every call that needs them.
#include "cuda/gpu_bvh_host.h"

#if !GLINT_HAVE_CUDA
#include "core/error.h"

namespace glint::cuda {
namespace {

[[noreturn]] void fail_without_cuda(const char* what) {
  fail("{}: glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)", what);
}

}  // namespace

struct GpuBvhSession::State {};

GpuBvhSession::GpuBvhSession(GpuBvhBuilder, const accel::BuildOptions&) { fail_without_cuda("the GPU BVH builders"); }
GpuBvhSession::~GpuBvhSession() = default;
double GpuBvhSession::build(const accel::TriangleMesh&) { fail_without_cuda("the GPU BVH builders"); }
void GpuBvhSession::upload(const accel::Bvh&) { fail_without_cuda("the GPU BVH builders"); }
double GpuBvhSession::refit(const accel::TriangleMesh&) { fail_without_cuda("refit on the GPU"); }
accel::Bvh GpuBvhSession::download() const { fail_without_cuda("the GPU BVH builders"); }

accel::Bvh build_bvh_on_gpu(GpuBvhBuilder, const accel::TriangleMesh&, const accel::BuildOptions&) {
  fail_without_cuda("the GPU BVH builders");
}
accel::Bvh refit_on_gpu(const accel::Bvh&, const accel::TriangleMesh&) { fail_without_cuda("refit on the GPU"); }
RefitTogetherResult refit_together_on_gpu(std::span<const accel::Bvh>,
                                          std::span<const std::vector<accel::TriangleMesh>>) {
  fail_without_cuda("refit on the GPU");
}
uint32_t measure_depth_on_gpu(const accel::Bvh&) { fail_without_cuda("measure_depth on the GPU"); }

}  // namespace glint::cuda
#endif
