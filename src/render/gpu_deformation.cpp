#include "render/gpu_deformation.h"

#include "core/error.h"

#include <epoxy/gl.h>

namespace glint::render {
namespace {

// The CUDA half poses only the tracer's device positions (no GL vertex buffer: GL poses its own).
std::unique_ptr<cuda::GpuSceneDeformer> tracer_deformer(const SceneDeformers& deformers, FramePipeline& pipeline) {
  const rt::RayTracer* tracer = pipeline.ray_tracer();
  if (tracer == nullptr || pipeline.gl_tracing() != nullptr) return nullptr;
  if (pipeline.device_tracing() == nullptr)
    fail("--deform-on gpu needs a GPU ray tracer (--backend cuda, optix or gl): the {} backend builds from host "
         "vertices, which the GPU deformer does not update; use --deform-on cpu",
         tracer->name());
  return std::make_unique<cuda::GpuSceneDeformer>(deformers, *pipeline.device_tracing());
}

}  // namespace

GpuDeformation::GpuDeformation(const SceneDeformers& deformers, FramePipeline& pipeline)
    : gl_(deformers, pipeline.raster().gpu_scene()),
      cuda_(tracer_deformer(deformers, pipeline)),
      gl_tracer_(pipeline.gl_tracing()) {
  if (gl_tracer_ == nullptr) return;
  for (std::size_t k = 0; k < gl_.meshes().size(); ++k) {
    const rt::GlTracing::VertexRange range = gl_tracer_->gl_positions(gl_.meshes()[k]);
    if (range.vertex_count != deformers.deformers()[k].vertex_count())
      fail("GPU deformation: mesh '{}' has {} vertices in the gl backend's structures but {} in its deformer",
           deformers.deformers()[k].mesh_name(), range.vertex_count, deformers.deformers()[k].vertex_count());
  }
}

GpuDeformation::~GpuDeformation() = default;

std::vector<std::uint32_t> GpuDeformation::apply(int frame) {
  if (gl_tracer_) target_tracer_positions();
  gl_.apply(frame);
  if (cuda_) return cuda_->apply(frame);
  return gl_.meshes();
}

void GpuDeformation::target_tracer_positions() {
  // Asked every frame: a host update may have laid the tracer's buffers out anew. Both sides hold
  // vec4 positions, every mesh's in one buffer.
  GLuint buffer = 0;
  tracer_first_vertex_.clear();
  for (const std::uint32_t mesh : gl_.meshes()) {
    const rt::GlTracing::VertexRange range = gl_tracer_->gl_positions(mesh);
    if ((buffer != 0 && range.buffer != buffer) || range.offset_bytes % sizeof(vec4) != 0)
      fail("GPU deformation: the gl backend's positions of mesh {} are not vec4s in the one buffer of the others'",
           mesh);
    buffer = range.buffer;
    tracer_first_vertex_.push_back(static_cast<std::uint32_t>(range.offset_bytes / sizeof(vec4)));
  }
  gl_.write_positions_to(buffer, tracer_first_vertex_);
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
