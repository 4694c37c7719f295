#include "cuda/gpu_bvh_host.h"

#include "cuda/device_query.h"
#include "cuda/gpu_bvh_build.h"
#include "cuda/gpu_mesh.h"

#include <span>
#include <string>
#include <vector>

namespace glint::cuda {
namespace {

// A stream and two events of its own. The stream is a blocking one (it synchronises with the
// legacy default stream) on purpose: GpuBvh::upload copies the parent links with a plain
// cudaMemcpy, whose DMA from pageable memory may still be running when it returns, and the refit
// on this stream must not start before it landed.
struct TimedStream {
  cudaStream_t stream = nullptr;
  cudaEvent_t start = nullptr, stop = nullptr;

  TimedStream() {
    GLINT_CUDA_CHECK(cudaStreamCreate(&stream));
    GLINT_CUDA_CHECK(cudaEventCreate(&start));
    GLINT_CUDA_CHECK(cudaEventCreate(&stop));
  }
  ~TimedStream() {  // not checked: a destructor, and failures here leak only
    if (start) cudaEventDestroy(start);
    if (stop) cudaEventDestroy(stop);
    if (stream) cudaStreamDestroy(stream);
  }
  TimedStream(const TimedStream&) = delete;
  TimedStream& operator=(const TimedStream&) = delete;

  // Milliseconds between the events, once the stream reached the second.
  double elapsed_ms() const {
    GLINT_CUDA_CHECK(cudaEventSynchronize(stop));
    float ms = 0.0f;
    GLINT_CUDA_CHECK(cudaEventElapsedTime(&ms, start, stop));
    return ms;
  }
};

// The mesh and a BVH over it on the GPU: what the session and the one-shot functions share.
struct DeviceStructure {
  TimedStream timing;
  GpuMesh mesh;
  GpuBvh bvh;
  DeviceBuffer<uint32_t> refit_counters;
  std::string builder_name;  // of the BVH in `bvh`

  // This structure as one entry of refit_meshes_gpu.
  MeshRefit mesh_refit() { return {&bvh, mesh.view(), &refit_counters}; }

  // The frame's refit (refit_meshes_gpu) with one mesh: the leaves are boxed from the triangles in
  // the timed launch itself.
  double refit(const accel::TriangleMesh& moved_host_mesh) {
    if (!bvh.refittable)
      fail_message("refit on the GPU: the BVH (builder '" + builder_name + "') is not refittable; rebuild it instead");
    if (moved_host_mesh.triangle_count != bvh.prim_indices.size())
      fail_message("refit on the GPU: " + std::to_string(moved_host_mesh.triangle_count) +
                   " triangles for a BVH over " + std::to_string(bvh.prim_indices.size()) + " primitives");
    mesh.upload(moved_host_mesh, timing.stream);
    const MeshRefit refit = mesh_refit();
    GLINT_CUDA_CHECK(cudaEventRecord(timing.start, timing.stream));
    refit_meshes_gpu(std::span<const MeshRefit>(&refit, 1), timing.stream);
    GLINT_CUDA_CHECK(cudaEventRecord(timing.stop, timing.stream));
    return timing.elapsed_ms();
  }

  accel::Bvh download() const {
    GLINT_CUDA_CHECK(cudaStreamSynchronize(timing.stream));  // GpuBvh::download copies on the default stream
    const uint32_t depth = measure_depth(bvh, timing.stream);
    accel::Bvh host = bvh.download(builder_name.c_str());
    host.depth = depth;
    return host;
  }
};

}  // namespace

struct GpuBvhSession::State {
  State(GpuBvhBuilder builder, const accel::BuildOptions& options) : build(builder, options) {}

  GpuBvhBuild build;
  DeviceBuffer<Aabb> boxes;  // the builder's input: one box per triangle
  DeviceStructure structure;
  double last_build_ms = 0.0;
};

GpuBvhSession::GpuBvhSession(GpuBvhBuilder builder, const accel::BuildOptions& options) {
  require_cuda_gpu("the GPU BVH builders");
  state_ = std::make_unique<State>(builder, options);
}

GpuBvhSession::~GpuBvhSession() = default;

double GpuBvhSession::build(const accel::TriangleMesh& host_mesh) {
  DeviceStructure& s = state_->structure;
  s.mesh.upload(host_mesh, s.timing.stream);
  state_->boxes.resize(host_mesh.triangle_count);
  compute_triangle_boxes(s.mesh.view(), state_->boxes.data(), s.timing.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.timing.start, s.timing.stream));
  state_->build.build(state_->boxes.data(), host_mesh.triangle_count, s.bvh, s.timing.stream);
  GLINT_CUDA_CHECK(cudaEventRecord(s.timing.stop, s.timing.stream));
  s.builder_name = gpu_builder_name(state_->build.builder());
  state_->last_build_ms = s.timing.elapsed_ms();
  return state_->last_build_ms;
}

void GpuBvhSession::upload(const accel::Bvh& bvh) {
  DeviceStructure& s = state_->structure;
  s.bvh.upload(bvh, s.timing.stream);
  s.builder_name = bvh.builder;
}

double GpuBvhSession::refit(const accel::TriangleMesh& moved_host_mesh) {
  return state_->structure.refit(moved_host_mesh);
}

accel::Bvh GpuBvhSession::download() const {
  accel::Bvh bvh = state_->structure.download();
  bvh.build_ms = state_->last_build_ms;
  return bvh;
}

accel::Bvh build_bvh_on_gpu(GpuBvhBuilder builder, const accel::TriangleMesh& host_mesh,
                            const accel::BuildOptions& options) {
  GpuBvhSession session(builder, options);
  session.build(host_mesh);
  return session.download();
}

accel::Bvh refit_on_gpu(const accel::Bvh& bvh, const accel::TriangleMesh& moved_host_mesh) {
  require_cuda_gpu("refit on the GPU");
  DeviceStructure structure;
  structure.bvh.upload(bvh, structure.timing.stream);
  structure.builder_name = bvh.builder;
  structure.refit(moved_host_mesh);
  accel::Bvh refitted = structure.download();
  refitted.build_ms = bvh.build_ms;
  return refitted;
}

RefitTogetherResult refit_together_on_gpu(std::span<const accel::Bvh> bvhs,
                                          std::span<const std::vector<accel::TriangleMesh>> poses) {
  require_cuda_gpu("refit on the GPU");
  for (const std::vector<accel::TriangleMesh>& pose : poses)
    if (pose.size() != bvhs.size())
      fail_message("refit_together_on_gpu: " + std::to_string(bvhs.size()) + " BVHs for a pose of " +
                   std::to_string(pose.size()) + " meshes");
  // Every upload and refit on the first structure's stream, so each launch sees its uploads.
  std::vector<DeviceStructure> structures(bvhs.size());
  if (structures.empty()) return {};
  const cudaStream_t stream = structures.front().timing.stream;
  for (std::size_t i = 0; i < bvhs.size(); ++i) {
    structures[i].bvh.upload(bvhs[i], stream);
    structures[i].builder_name = bvhs[i].builder;
  }
  for (const std::vector<accel::TriangleMesh>& pose : poses) {
    std::vector<MeshRefit> refits;
    for (std::size_t i = 0; i < bvhs.size(); ++i) {
      structures[i].mesh.upload(pose[i], stream);
      refits.push_back(structures[i].mesh_refit());
    }
    refit_meshes_gpu(refits, stream);
  }
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
  RefitTogetherResult result;
  for (std::size_t i = 0; i < structures.size(); ++i) {
    result.bvhs.push_back(structures[i].download());
    result.bvhs.back().build_ms = bvhs[i].build_ms;
    result.arrival_counters.push_back(structures[i].refit_counters.download());
  }
  return result;
}

uint32_t measure_depth_on_gpu(const accel::Bvh& bvh) {
  require_cuda_gpu("measure_depth on the GPU");
  DeviceStructure structure;
  structure.bvh.upload(bvh, structure.timing.stream);
  return measure_depth(structure.bvh, structure.timing.stream);
}

}  // namespace glint::cuda
