// A build without CUDA: GPU structures are unavailable, said at construction.
#include "cuda/gpu_bench_structure.h"

#if !GLINT_HAVE_CUDA
#include "core/error.h"

namespace glint::cuda {

struct GpuBenchStructure::State {};

GpuBenchStructure::GpuBenchStructure(accel::BvhBuilder, const accel::BuildOptions&, TraceKernel) {
  fail("accel-bench --backend cuda: glint was built without CUDA (GLINT_CUDA=OFF or no nvcc at configure time)");
}
GpuBenchStructure::~GpuBenchStructure() = default;
double GpuBenchStructure::build(const accel::TriangleMesh&) { return 0.0; }
std::optional<double> GpuBenchStructure::refit(const accel::TriangleMesh&) { return std::nullopt; }
double GpuBenchStructure::trace_closest(std::span<const accel::Ray>, std::span<accel::Hit>) { return 0.0; }
accel::Bvh GpuBenchStructure::download() const { return {}; }
std::size_t GpuBenchStructure::memory_bytes() const { return 0; }

}  // namespace glint::cuda
#endif
