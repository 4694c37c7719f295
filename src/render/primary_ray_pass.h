#pragma once
// PrimaryRayPass: the visibility G-buffer's ids from camera rays instead of the id draw
// (PrimaryVisibility::rt, docs/render.md "Ray-traced primary visibility"), in RasterPipeline's
// "gbuffer" step before VisibilityGBufferPass:
//   1. primary_rays.comp.glsl: one ray per pixel centre, dense (ray i is pixel y * width + x), from
//      the frame's inverse view and projection (FrameConstants UBO, bound by RasterPipeline);
//   2. the ray tracer's closest-hit query over all width x height rays (OcclusionBuffers with
//      RayQuery::closest: mapped host buffers and a fence on CPU backends, GL buffers shared with
//      CUDA on GPU backends, as RayTracedShadows);
//   3. primary_ids.comp.glsl: RasterTargets::visibility_id from the hits.
// The depth target is not written: no frame pass reads it (SSR and the depth view read positions).
// The tracer is not owned: FramePipeline's, shared with shadows and reflections.
#include "accel/ray.h"
#include "gl/shader_program.h"
#include "render/occlusion_buffers.h"
#include "render/raster_targets.h"
#include "rt/ray_tracer.h"

#include <span>

namespace glint::render {

class PrimaryRayPass {
public:
  // The targets must hold visibility_id and outlive this; `tracer` must be built over the scene the
  // pipeline draws and outlive this. glint::Error otherwise. Needs a current GL context.
  PrimaryRayPass(const RasterTargets& targets, rt::RayTracer& tracer);

  // Writes visibility_id for this frame (FrameConstants bound). Ends with a barrier that makes the
  // ids visible to image loads. With a CPU backend the CPU waits for step 1 in between.
  void run();

  // CPU backends: the last run's rays and hits, for tests; glint::Error for a GPU backend.
  std::span<const accel::Ray> rays() const { return buffers_.rays(); }
  std::span<const accel::Hit> hits() const { return buffers_.hits(); }

private:
  const RasterTargets* targets_;
  OcclusionBuffers buffers_;
  ShaderProgram ray_program_, id_program_;
};

}  // namespace glint::render
