#pragma once
// VisibilityIdPass: the raster half of the visibility G-buffer. Draws every instance of the GpuScene
// writing only depth and the visible triangle's id, with a fragment shader that reads nothing:
//   inputs:  GpuScene (vertices, instances), FrameConstants UBO at kFrameConstantsBinding
//   outputs: RasterTargets visibility_id (kVisibilityIdFormat: x = instance + 1, 0 background;
//            y = triangle number in its mesh), depth (the same depths GBufferPass writes)
// VisibilityGBufferPass turns the ids into the G-buffer images. Like GBufferPass: no face culling.
#include "core/math.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/raster_targets.h"

#include <vector>

namespace glint::render {

class VisibilityIdPass {
public:
  // The targets must outlive the pass and hold visibility_id (RasterTargets(w, h, true)); throws
  // glint::Error otherwise.
  explicit VisibilityIdPass(const RasterTargets& targets);

  void run(const GpuScene& scene);

private:
  const RasterTargets* targets_;
  GlFramebuffer framebuffer_;
  ShaderProgram program_;
};

// The id image on the CPU, top row first (x + y * width): {instance + 1, triangle}, {0, 0} for the
// background. Waits for the GPU: tests and debugging only.
std::vector<glm::uvec2> read_visibility_ids(GLuint texture, int width, int height);

}  // namespace glint::render
