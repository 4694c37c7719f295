#include "cuda/gpu_scene_deformer.h"

#include "cuda/cuda_check.h"
#include "cuda/device_query.h"
#include "cuda/gpu_sine_deformer.h"
#include "cuda/cuda_span.h"
#include "cuda/gpu_span_pool.h"

#include <optional>
#include <string>

namespace glint::cuda {

struct GpuSceneDeformer::State {
  const SceneDeformers* deformers = nullptr;
  std::vector<GpuSineDeformer> meshes;  // parallel to deformers->meshes()
  rt::DeviceTracing* tracer = nullptr;
  GpuSpanPool<CudaSpan> timed{"GPU deformer"};  // one span per apply, read once by the frame loop
  std::optional<std::uint64_t> last_apply;
};

GpuSceneDeformer::GpuSceneDeformer(const SceneDeformers& deformers, rt::DeviceTracing& tracer)
    : state_(std::make_unique<State>()) {
  require_cuda_gpu("--deform-on gpu");
  State& s = *state_;
  s.deformers = &deformers;
  for (const SineDeformer& deformer : deformers.deformers()) s.meshes.emplace_back(deformer);
  s.tracer = &tracer;
}

GpuSceneDeformer::~GpuSceneDeformer() = default;

std::vector<std::uint32_t> GpuSceneDeformer::apply(int frame) {
  State& s = *state_;
  const float time_seconds = s.deformers->time_at(frame);
  const auto stream = static_cast<cudaStream_t>(s.tracer->stream());  // so its update follows the poses
  const std::uint64_t ticket = start_span(s.timed, stream);
  for (std::size_t k = 0; k < s.meshes.size(); ++k)
    s.meshes[k].apply(time_seconds, s.tracer->device_positions(s.deformers->meshes()[k]), stream);
  stop_span(s.timed, ticket, stream);
  s.last_apply = ticket;
  return s.deformers->meshes();
}

std::uint64_t GpuSceneDeformer::last_apply() const {
  if (!state_->last_apply) fail_message("GPU deformer: no apply() to time yet");
  return *state_->last_apply;
}

std::optional<double> GpuSceneDeformer::apply_ms(std::uint64_t ticket, bool wait) {
  return state_->timed.read_ms(ticket, wait);
}

GpuPosedMesh pose_mesh_on_gpu(const SineDeformer& deformer, float time_seconds) {
  require_cuda_gpu("the GPU deformer");
  GpuSineDeformer gpu(deformer);
  DeviceBuffer<vec3> positions(gpu.vertex_count());
  DeviceBuffer<PosedVertex> vertices(gpu.vertex_count());
  gpu.apply_with_normals(time_seconds, positions.data(), vertices.data(), nullptr);
  GLINT_CUDA_CHECK(cudaDeviceSynchronize());
  GpuPosedMesh posed;
  posed.positions = positions.download();
  for (const PosedVertex& vertex : vertices.download()) posed.normals.push_back(vertex.normal);
  return posed;
}

}  // namespace glint::cuda
