#include "cuda/gpu_bench_kdtree.h"

#include "cuda/cuda_check.h"
#include "cuda/cuda_stream_events.h"
#include "cuda/device_query.h"
#include "cuda/gpu_mesh.h"
#include "cuda/gpu_trace.h"

#include <chrono>
#include <string>

namespace glint::cuda {

struct GpuBenchKdTree::State {
  accel::KdTree tree;
  GpuMesh mesh;
  DeviceBuffer<accel::KdNode> nodes;
  DeviceBuffer<uint32_t> prim_indices;
  DeviceBuffer<accel::Ray> rays;
  DeviceBuffer<accel::Hit> hits;
  bool built = false;
  CudaEvent start, stop;
  // Last, so it is destroyed first: its destructor waits for the work still using the buffers above.
  CudaStream stream{cudaStreamNonBlocking};

  double elapsed() const { return elapsed_ms(start, stop); }
};

// The GPU check comes before State: its CUDA events and stream need a GPU.
GpuBenchKdTree::GpuBenchKdTree()
    : state_((require_cuda_gpu("accel-bench cuda-kdtree"), std::make_unique<State>())) {}

GpuBenchKdTree::~GpuBenchKdTree() = default;

double GpuBenchKdTree::build(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  s.mesh.upload(mesh, s.stream.get());
  s.tree = accel::build_kdtree(mesh);
  s.start.record(s.stream.get());
  s.nodes.upload(std::span<const accel::KdNode>(s.tree.nodes), s.stream.get());
  s.prim_indices.upload(std::span<const uint32_t>(s.tree.prim_indices), s.stream.get());
  s.stop.record(s.stream.get());
  s.built = true;
  return s.tree.build_ms + s.elapsed();
}

double GpuBenchKdTree::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
  State& s = *state_;
  if (!s.built) fail_message("accel-bench cuda-kdtree: trace before build");
  if (rays.size() != hits.size())
    fail_message("accel-bench cuda-kdtree: " + std::to_string(rays.size()) + " rays but " +
                 std::to_string(hits.size()) + " hits");
  if (rays.size() > 0xFFFFFFFFu) fail_message("accel-bench cuda-kdtree: more than 2^32 - 1 rays in one call");
  if (rays.empty()) return 0.0;
  s.rays.upload(rays, s.stream.get());
  s.hits.resize(rays.size());
  const accel::KdTreeView view{s.nodes.data(), s.prim_indices.data(), static_cast<uint32_t>(s.tree.nodes.size()),
                               s.tree.bounds};
  s.start.record(s.stream.get());
  launch_trace_closest(view, s.mesh.view(), s.rays.data(), s.hits.data(), static_cast<uint32_t>(rays.size()),
                       s.stream.get());
  s.stop.record(s.stream.get());
  GLINT_CUDA_CHECK(
      cudaMemcpyAsync(hits.data(), s.hits.data(), hits.size_bytes(), cudaMemcpyDeviceToHost, s.stream.get()));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream.get()));
  return s.elapsed();
}

const accel::KdTree& GpuBenchKdTree::tree() const { return state_->tree; }

}  // namespace glint::cuda
