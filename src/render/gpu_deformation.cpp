#include "render/gpu_deformation.h"

#include "core/error.h"

#include <cstddef>

namespace glint::render {

static_assert(sizeof(GpuVertex) == sizeof(cuda::DeformedGlVertex) &&
                  offsetof(GpuVertex, normal_v) == offsetof(cuda::DeformedGlVertex, normal_v),
              "the GPU deformer writes GpuVertex records");

std::unique_ptr<cuda::GpuSceneDeformer> make_gpu_deformer(const SceneDeformers& deformers, FramePipeline& pipeline) {
  const rt::RayTracer* tracer = pipeline.ray_tracer();
  if (tracer != nullptr && pipeline.device_tracing() == nullptr)
    fail("--deform-on gpu needs a GPU ray tracer (--backend cuda): the {} backend builds from host vertices, which "
         "the GPU deformer does not update; use --deform-on cpu",
         tracer->name());
  std::vector<std::uint32_t> base_vertex;
  for (const GpuMeshRange& range : pipeline.raster().gpu_scene().mesh_ranges()) base_vertex.push_back(range.base_vertex);
  return std::make_unique<cuda::GpuSceneDeformer>(deformers, pipeline.raster().gpu_scene().vertex_buffer(),
                                                  std::move(base_vertex), pipeline.device_tracing());
}

}  // namespace glint::render
