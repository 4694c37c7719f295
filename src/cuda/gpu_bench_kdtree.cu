#include "cuda/gpu_bench_kdtree.h"

#include "cuda/cuda_check.h"
#include "cuda/device_query.h"
#include "cuda/gpu_mesh.h"
#include "cuda/gpu_trace.h"

#include <chrono>
#include <string>

namespace glint::cuda {

struct GpuBenchKdTree::State {
  cudaStream_t stream = nullptr;
  cudaEvent_t start = nullptr, stop = nullptr;
  accel::KdTree tree;
  GpuMesh mesh;
  DeviceBuffer<accel::KdNode> nodes;
  DeviceBuffer<uint32_t> prim_indices;
  DeviceBuffer<accel::Ray> rays;
  DeviceBuffer<accel::Hit> hits;
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
};

GpuBenchKdTree::GpuBenchKdTree() : state_(std::make_unique<State>()) {
  require_cuda_gpu("accel-bench cuda-kdtree");
  GLINT_CUDA_CHECK(cudaStreamCreateWithFlags(&state_->stream, cudaStreamNonBlocking));
  GLINT_CUDA_CHECK(cudaEventCreate(&state_->start));
  GLINT_CUDA_CHECK(cudaEventCreate(&state_->stop));
}

GpuBenchKdTree::~GpuBenchKdTree() = default;

double GpuBenchKdTree::build(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  s.mesh.upload(mesh, s.stream);
  s.tree = accel::build_kdtree(mesh);
  GLINT_CUDA_CHECK(cudaEventRecord(s.start, s.stream));
  s.nodes.upload(std::span<const accel::KdNode>(s.tree.nodes), s.stream);
  s.prim_indices.upload(std::span<const uint32_t>(s.tree.prim_indices), s.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.stop, s.stream));
  s.built = true;
  return s.tree.build_ms + s.elapsed_ms();
}

double GpuBenchKdTree::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
  State& s = *state_;
  if (!s.built) fail_message("accel-bench cuda-kdtree: trace before build");
  if (rays.size() != hits.size())
    fail_message("accel-bench cuda-kdtree: " + std::to_string(rays.size()) + " rays but " +
                 std::to_string(hits.size()) + " hits");
  if (rays.size() > 0xFFFFFFFFu) fail_message("accel-bench cuda-kdtree: more than 2^32 - 1 rays in one call");
  if (rays.empty()) return 0.0;
  s.rays.upload(rays, s.stream);
  s.hits.resize(rays.size());
  const accel::KdTreeView view{s.nodes.data(), s.prim_indices.data(), static_cast<uint32_t>(s.tree.nodes.size()),
                               s.tree.bounds};
  GLINT_CUDA_CHECK(cudaEventRecord(s.start, s.stream));
  launch_trace_closest(view, s.mesh.view(), s.rays.data(), s.hits.data(), static_cast<uint32_t>(rays.size()),
                       s.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.stop, s.stream));
  GLINT_CUDA_CHECK(cudaMemcpyAsync(hits.data(), s.hits.data(), hits.size_bytes(), cudaMemcpyDeviceToHost, s.stream));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream));
  return s.elapsed_ms();
}

const accel::KdTree& GpuBenchKdTree::tree() const { return state_->tree; }

}  // namespace glint::cuda
