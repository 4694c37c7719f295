#pragma once
// VisibilityGBufferPass: the compute half of the visibility G-buffer. One invocation per pixel
// rebuilds what GBufferPass would have written there from the pixel's {instance, triangle} id and
// the GpuScene buffers (shaders/visibility_gbuffer.comp.glsl: perspective-correct barycentrics of
// the pixel centre, surface_point() shared with hit shading, texture LOD from the uv differences
// across the pixel's 2x2 quad as the raster path's sampler takes them, through textureGrad; on
// Mesa's software renderers, where that is ~60x slower, filtered trilinearly in the shader).
//   inputs:  RasterTargets visibility_id (VisibilityIdPass), GpuScene, FrameConstants UBO
//   outputs: RasterTargets albedo_reflectivity, world_position, world_normal_roughness, material_id
//            (formats and meanings of GBufferPass; depth is VisibilityIdPass's); with a
//            SurfaceMotion also its world_motion (include/surface_motion.glsl)
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/raster_targets.h"
#include "render/surface_motion.h"

namespace glint::render {

class VisibilityGBufferPass {
public:
  // The targets (and `motion`, when given) must outlive the pass and the targets hold visibility_id;
  // throws glint::Error otherwise.
  explicit VisibilityGBufferPass(const RasterTargets& targets, const SurfaceMotion* motion = nullptr);

  // Ends with a barrier that makes the images visible to later texture fetches, image loads and
  // readbacks.
  void run(const GpuScene& scene);

private:
  const RasterTargets* targets_;
  const SurfaceMotion* motion_;
  ShaderProgram program_;
};

}  // namespace glint::render
