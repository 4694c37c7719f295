#include "render/visibility_id_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/gbuffer_pass.h"

namespace glint::render {

VisibilityIdPass::VisibilityIdPass(const RasterTargets& targets)
    : targets_(&targets),
      framebuffer_(create_framebuffer()),
      program_(ShaderProgram::from_embedded({"visibility.vert.glsl", "visibility.frag.glsl"})) {
  if (targets.visibility_id.id() == 0) fail("visibility id pass: the raster targets have no visibility id image");
  const GLuint fb = framebuffer_.id();
  glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, targets.visibility_id.id(), 0);
  glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, targets.depth.id(), 0);
  glNamedFramebufferDrawBuffer(fb, GL_COLOR_ATTACHMENT0);
  require_framebuffer_complete(framebuffer_, "visibility ids");
  check_gl("visibility id pass set-up");
}

void VisibilityIdPass::run(const GpuScene& scene) {
  GlPassScope scope("visibility_ids");
  const GLuint fb = framebuffer_.id();
  const GLuint background[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearNamedFramebufferuiv(fb, GL_COLOR, 0, background);
  glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);

  draw_scene_depth_tested(fb, targets_->width, targets_->height, program_, scene);
  check_gl("visibility id pass");
}

std::vector<glm::uvec2> read_visibility_ids(GLuint texture, int width, int height) {
  if (width <= 0 || height <= 0) fail("visibility ids readback: invalid size {}x{}", width, height);
  const std::size_t w = static_cast<std::size_t>(width), h = static_cast<std::size_t>(height);
  std::vector<glm::uvec2> rows(w * h), ids(w * h);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture, 0, GL_RG_INTEGER, GL_UNSIGNED_INT, static_cast<GLsizei>(rows.size() * sizeof(glm::uvec2)),
                    rows.data());
  check_gl("visibility ids readback");
  for (std::size_t y = 0; y < h; ++y)  // GL's row 0 is the bottom
    for (std::size_t x = 0; x < w; ++x) ids[(h - 1 - y) * w + x] = rows[y * w + x];
  return ids;
}

}  // namespace glint::render
