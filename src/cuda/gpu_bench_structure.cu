#include "cuda/gpu_bench_structure.h"

#include "cuda/cuda_check.h"
#include "cuda/cuda_stream_events.h"
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
  GpuMesh mesh;
  DeviceBuffer<Aabb> boxes;  // the GPU builders' input: one box per triangle
  GpuBvh bvh;
  DeviceBuffer<uint32_t> refit_counters;
  DeviceBuffer<accel::Ray> rays;
  DeviceBuffer<accel::Hit> hits;
  DeviceBuffer<uint32_t> overflow;
  DeviceBuffer<uint32_t> next_ray;  // the persistent kernel's ray counter
  TraceKernel kernel = kDefaultTraceKernel;
  bool built = false;
  CudaEvent start, stop;
  // Last, so it is destroyed first: its destructor waits for the work still using the buffers above.
  CudaStream stream{cudaStreamNonBlocking};

  double elapsed() const { return elapsed_ms(start, stop); }
  void require_built(const char* what) const {
    if (!built) fail_message(std::string("accel-bench cuda: ") + what + " before build");
  }
};

// The GPU check comes before State: its CUDA events and stream need a GPU.
GpuBenchStructure::GpuBenchStructure(accel::BvhBuilder builder, const accel::BuildOptions& options,
                                     TraceKernel kernel)
    : state_((require_cuda_gpu("accel-bench --backend cuda"), std::make_unique<State>())) {
  State& s = *state_;
  s.builder = builder;
  s.options = options;
  s.kernel = kernel;
  if (builder == accel::BvhBuilder::lbvh) s.gpu_builder.emplace(GpuBvhBuilder::lbvh, options);
  if (builder == accel::BvhBuilder::ploc) s.gpu_builder.emplace(GpuBvhBuilder::ploc, options);
  s.overflow.resize(1);
  s.next_ray.resize(1);
}

GpuBenchStructure::~GpuBenchStructure() = default;

double GpuBenchStructure::build(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  s.mesh.upload(mesh, s.stream.get());
  if (s.gpu_builder) {
    s.start.record(s.stream.get());
    s.boxes.resize(mesh.triangle_count);
    compute_triangle_boxes(s.mesh.view(), s.boxes.data(), s.stream.get());
    s.gpu_builder->build(s.boxes.data(), mesh.triangle_count, s.bvh, s.stream.get());
    s.stop.record(s.stream.get());
    s.built = true;
    return s.elapsed();
  }
  const accel::Bvh host_bvh = accel::build_bvh(s.builder, mesh, s.options);
  s.start.record(s.stream.get());
  s.bvh.upload(host_bvh, s.stream.get());
  s.stop.record(s.stream.get());
  s.built = true;
  return host_bvh.build_ms + s.elapsed();
}

std::optional<double> GpuBenchStructure::refit(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  s.require_built("refit");
  if (!s.bvh.refittable) return std::nullopt;
  if (mesh.triangle_count != s.mesh.triangle_count())
    fail_message("accel-bench cuda: refit with " + std::to_string(mesh.triangle_count) + " triangles, built with " +
                 std::to_string(s.mesh.triangle_count()));
  s.mesh.upload(mesh, s.stream.get());
  // The frame's refit (CudaRayTracer's): one launch boxes the leaves from the triangles and climbs.
  const MeshRefit refit{&s.bvh, s.mesh.view(), &s.refit_counters};
  s.start.record(s.stream.get());
  refit_meshes_gpu(std::span<const MeshRefit>(&refit, 1), s.stream.get());
  s.stop.record(s.stream.get());
  return s.elapsed();
}

double GpuBenchStructure::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
  State& s = *state_;
  s.require_built("trace");
  if (rays.size() != hits.size())
    fail_message("accel-bench cuda: " + std::to_string(rays.size()) + " rays but " + std::to_string(hits.size()) +
                 " hits");
  if (rays.empty()) return 0.0;
  if (rays.size() > 0xFFFFFFFFu) fail_message("accel-bench cuda: more than 2^32 - 1 rays in one call");
  s.rays.upload(rays, s.stream.get());
  s.hits.resize(rays.size());
  s.overflow.fill_zero(s.stream.get());
  const accel::Blas blas{s.bvh.view(), s.mesh.view()};
  s.start.record(s.stream.get());
  launch_trace_closest(blas,
                       {s.rays.data(), s.hits.data(), nullptr, static_cast<uint32_t>(rays.size()), s.overflow.data(),
                        s.next_ray.data(), s.kernel},
                       s.stream.get());
  s.stop.record(s.stream.get());
  uint32_t overflowed = 0;
  GLINT_CUDA_CHECK(
      cudaMemcpyAsync(hits.data(), s.hits.data(), hits.size_bytes(), cudaMemcpyDeviceToHost, s.stream.get()));
  GLINT_CUDA_CHECK(cudaMemcpyAsync(&overflowed, s.overflow.data(), sizeof(uint32_t), cudaMemcpyDeviceToHost, s.stream.get()));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream.get()));
  if (overflowed)
    fail_message("accel-bench cuda: a traversal stack overflowed (" + std::string(accel::builder_name(s.builder)) +
                 " BVH deeper than " + std::to_string(accel::kMaxBvhDepth) + " levels)");
  return s.elapsed();
}

accel::Bvh GpuBenchStructure::download() const {
  State& s = *state_;
  s.require_built("download");
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream.get()));
  accel::Bvh bvh = s.bvh.download(accel::builder_name(s.builder).data());
  bvh.depth = measure_depth(s.bvh, s.stream.get());
  return bvh;
}

std::size_t GpuBenchStructure::memory_bytes() const { return state_->bvh.memory_bytes(); }

}  // namespace glint::cuda
