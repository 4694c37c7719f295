#include "cuda/gpu_bench_structure.h"

#include "cuda/cuda_check.h"
#include "cuda/device_query.h"
#include "cuda/gpu_bvh_build.h"
#include "cuda/gpu_mesh.h"
#include "cuda/gpu_trace.h"

#include <chrono>
#include <optional>
#include <string>

namespace glint::cuda {

struct GpuBenchStructure::State {
  accel::BvhBuilder builder = accel::BvhBuilder::sah;
  accel::BuildOptions options;
  std::optional<GpuBvhBuild> gpu_builder;  // lbvh, ploc
  cudaStream_t stream = nullptr;
  cudaEvent_t start = nullptr, stop = nullptr;
  GpuMesh mesh;
  DeviceBuffer<Aabb> boxes;
  GpuBvh bvh;
  DeviceBuffer<uint32_t> refit_counters;
  DeviceBuffer<accel::Ray> rays;
  DeviceBuffer<accel::Hit> hits;
  DeviceBuffer<uint32_t> overflow;
  bool built = false;

  ~State() {
    if (stream) cudaStreamSynchronize(stream);
    if (start) cudaEventDestroy(start);
    if (stop) cudaEventDestroy(stop);
    if (stream) cudaStreamDestroy(stream);
  }

  double elapsed_ms() {
    GLINT_CUDA_CHECK(cudaEventSynchronize(stop));
    float ms = 0.0f;
    GLINT_CUDA_CHECK(cudaEventElapsedTime(&ms, start, stop));
    return ms;
  }
  void require_built(const char* what) const {
    if (!built) fail_message(std::string("accel-bench cuda: ") + what + " before build");
  }
};

GpuBenchStructure::GpuBenchStructure(accel::BvhBuilder builder, const accel::BuildOptions& options)
    : state_(std::make_unique<State>()) {
  require_cuda_gpu("accel-bench --backend cuda");
  State& s = *state_;
  s.builder = builder;
  s.options = options;
  if (builder == accel::BvhBuilder::lbvh) s.gpu_builder.emplace(GpuBvhBuilder::lbvh, options);
  if (builder == accel::BvhBuilder::ploc) s.gpu_builder.emplace(GpuBvhBuilder::ploc, options);
  GLINT_CUDA_CHECK(cudaStreamCreateWithFlags(&s.stream, cudaStreamNonBlocking));
  GLINT_CUDA_CHECK(cudaEventCreate(&s.start));
  GLINT_CUDA_CHECK(cudaEventCreate(&s.stop));
  s.overflow.resize(1);
}

GpuBenchStructure::~GpuBenchStructure() = default;

double GpuBenchStructure::build(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  s.mesh.upload(mesh, s.stream);
  if (s.gpu_builder) {
    GLINT_CUDA_CHECK(cudaEventRecord(s.start, s.stream));
    s.boxes.resize(mesh.triangle_count);
    compute_triangle_boxes(s.mesh.view(), s.boxes.data(), s.stream);
    s.gpu_builder->build(s.boxes.data(), mesh.triangle_count, s.bvh, s.stream);
    GLINT_CUDA_CHECK(cudaEventRecord(s.stop, s.stream));
    s.built = true;
    return s.elapsed_ms();
  }
  const accel::Bvh host_bvh = accel::build_bvh(s.builder, mesh, s.options);
  GLINT_CUDA_CHECK(cudaEventRecord(s.start, s.stream));
  s.bvh.upload(host_bvh, s.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.stop, s.stream));
  s.built = true;
  return host_bvh.build_ms + s.elapsed_ms();
}

std::optional<double> GpuBenchStructure::refit(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  s.require_built("refit");
  if (!s.bvh.refittable) return std::nullopt;
  if (mesh.triangle_count != s.mesh.triangle_count())
    fail_message("accel-bench cuda: refit with " + std::to_string(mesh.triangle_count) + " triangles, built with " +
                 std::to_string(s.mesh.triangle_count()));
  s.mesh.upload(mesh, s.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.start, s.stream));
  s.boxes.resize(mesh.triangle_count);
  compute_triangle_boxes(s.mesh.view(), s.boxes.data(), s.stream);
  refit_gpu(s.bvh, s.boxes.data(), s.refit_counters, s.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.stop, s.stream));
  return s.elapsed_ms();
}

double GpuBenchStructure::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
  State& s = *state_;
  s.require_built("trace");
  if (rays.size() != hits.size())
    fail_message("accel-bench cuda: " + std::to_string(rays.size()) + " rays but " + std::to_string(hits.size()) +
                 " hits");
  if (rays.empty()) return 0.0;
  if (rays.size() > 0xFFFFFFFFu) fail_message("accel-bench cuda: more than 2^32 - 1 rays in one call");
  s.rays.upload(rays, s.stream);
  s.hits.resize(rays.size());
  s.overflow.fill_zero(s.stream);
  const accel::Blas blas{s.bvh.view(), s.mesh.view()};
  GLINT_CUDA_CHECK(cudaEventRecord(s.start, s.stream));
  launch_trace_closest(blas, s.rays.data(), s.hits.data(), nullptr, static_cast<uint32_t>(rays.size()),
                       s.overflow.data(), s.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.stop, s.stream));
  uint32_t overflowed = 0;
  GLINT_CUDA_CHECK(cudaMemcpyAsync(hits.data(), s.hits.data(), hits.size_bytes(), cudaMemcpyDeviceToHost, s.stream));
  GLINT_CUDA_CHECK(cudaMemcpyAsync(&overflowed, s.overflow.data(), sizeof(uint32_t), cudaMemcpyDeviceToHost, s.stream));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream));
  if (overflowed)
    fail_message("accel-bench cuda: a traversal stack overflowed (" + std::string(accel::builder_name(s.builder)) +
                 " BVH deeper than " + std::to_string(accel::kMaxBvhDepth) + " levels)");
  return s.elapsed_ms();
}

accel::Bvh GpuBenchStructure::download() const {
  State& s = *state_;
  s.require_built("download");
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream));
  accel::Bvh bvh = s.bvh.download(accel::builder_name(s.builder).data());
  bvh.depth = measure_depth(s.bvh, s.stream);
  return bvh;
}

std::size_t GpuBenchStructure::memory_bytes() const { return state_->bvh.memory_bytes(); }

}  // namespace glint::cuda
