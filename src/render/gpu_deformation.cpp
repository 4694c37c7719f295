#include "render/gpu_deformation.h"

#include "core/error.h"

namespace glint::render {
namespace {

// The CUDA half poses only the tracer's device positions (no GL vertex buffer: GL poses its own).
std::unique_ptr<cuda::GpuSceneDeformer> tracer_deformer(const SceneDeformers& deformers, FramePipeline& pipeline) {
  const rt::RayTracer* tracer = pipeline.ray_tracer();
  if (tracer == nullptr) return nullptr;
  if (pipeline.device_tracing() == nullptr)
    fail("--deform-on gpu needs a GPU ray tracer (--backend cuda): the {} backend builds from host vertices, which "
         "the GPU deformer does not update; use --deform-on cpu",
         tracer->name());
  return std::make_unique<cuda::GpuSceneDeformer>(deformers, *pipeline.device_tracing());
}

}  // namespace

GpuDeformation::GpuDeformation(const SceneDeformers& deformers, FramePipeline& pipeline)
    : gl_(deformers, pipeline.raster().gpu_scene()), cuda_(tracer_deformer(deformers, pipeline)) {}

GpuDeformation::~GpuDeformation() = default;

std::vector<std::uint32_t> GpuDeformation::apply(int frame) {
  gl_.apply(frame);
  if (cuda_) return cuda_->apply(frame);
  return gl_.meshes();
}

std::optional<std::uint64_t> GpuDeformation::last_cuda_apply() const {
  if (!cuda_) return std::nullopt;
  return cuda_->last_apply();
}

std::optional<double> GpuDeformation::cuda_apply_ms(std::uint64_t ticket, bool wait) {
  if (!cuda_) fail("GPU deformation: no CUDA deformer to time");
  return cuda_->apply_ms(ticket, wait);
}

}  // namespace glint::render
