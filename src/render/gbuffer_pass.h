#pragma once
// GBufferPass: rasterises every instance of the GpuScene into the G-buffer.
//   inputs:  GpuScene (vertices, instances, materials, texture array), FrameConstants UBO bound at
//            kFrameConstantsBinding
//   outputs: RasterTargets albedo_reflectivity, world_position (w = 1 geometry, 0 background),
//            world_normal_roughness, material_id (index + 1, 0 background), depth; with a
//            SurfaceMotion also its world_motion (0 background)
// No face culling: scenes are open sheets, and back faces must be seen (SSR tells them by normal).
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/raster_targets.h"
#include "render/surface_motion.h"

namespace glint::render {

// Draws every instance of `scene` with `program` into framebuffer `framebuffer` (width x height)
// under the depth state both G-buffer methods share (depth test less, no culling, no blending), so
// GBufferPass and VisibilityIdPass keep the same surface at every pixel. Unbinds the framebuffer.
void draw_scene_depth_tested(GLuint framebuffer, int width, int height, const ShaderProgram& program,
                             const GpuScene& scene);

class GBufferPass {
public:
  // The targets (and `motion`, when given) must outlive the pass.
  explicit GBufferPass(const RasterTargets& targets, const SurfaceMotion* motion = nullptr);

  void run(const GpuScene& scene);

private:
  const RasterTargets* targets_;
  const SurfaceMotion* motion_;
  GlFramebuffer framebuffer_;
  ShaderProgram program_;
};

}  // namespace glint::render
