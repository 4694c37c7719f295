// A build without CUDA: the GPU kd-tree is unavailable, said at construction.
#include "cuda/gpu_bench_kdtree.h"

#if !GLINT_HAVE_CUDA
#include "core/error.h"

namespace glint::cuda {

struct GpuBenchKdTree::State {
  accel::KdTree tree;
};

GpuBenchKdTree::GpuBenchKdTree() {
  fail("accel-bench cuda-kdtree: glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)");
}
GpuBenchKdTree::~GpuBenchKdTree() = default;
double GpuBenchKdTree::build(const accel::TriangleMesh&) { return 0.0; }
double GpuBenchKdTree::trace_closest(std::span<const accel::Ray>, std::span<accel::Hit>) { return 0.0; }
const accel::KdTree& GpuBenchKdTree::tree() const { return state_->tree; }

}  // namespace glint::cuda
#endif
