#include "render/gbuffer_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

#include <array>

namespace glint::render {

void draw_scene_depth_tested(GLuint framebuffer, int width, int height, const ShaderProgram& program,
                             const GpuScene& scene) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, width, height);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  program.use();
  scene.draw_all_instances();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

GBufferPass::GBufferPass(const RasterTargets& targets, const SurfaceMotion* motion)
    : targets_(&targets),
      motion_(motion),
      framebuffer_(create_framebuffer()),
      program_(ShaderProgram::from_embedded({"gbuffer.vert.glsl", "gbuffer.frag.glsl"})) {
  const GLuint fb = framebuffer_.id();
  glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT0, targets.albedo_reflectivity.id(), 0);
  glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT1, targets.world_position.id(), 0);
  glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT2, targets.world_normal_roughness.id(), 0);
  glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT3, targets.material_id.id(), 0);
  glNamedFramebufferTexture(fb, GL_DEPTH_ATTACHMENT, targets.depth.id(), 0);
  if (motion != nullptr) glNamedFramebufferTexture(fb, GL_COLOR_ATTACHMENT4, motion->world_motion(), 0);
  const std::array<GLenum, 5> buffers = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
                                         GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4};
  glNamedFramebufferDrawBuffers(fb, motion != nullptr ? 5 : 4, buffers.data());
  require_framebuffer_complete(framebuffer_, "G-buffer");
  check_gl("G-buffer pass set-up");
}

void GBufferPass::run(const GpuScene& scene) {
  GlPassScope scope("gbuffer");
  const GLuint fb = framebuffer_.id();
  // Background: everything 0 (position w = 0 and material id 0 mark it), depth at the far plane.
  const vec4 zero(0.0f);
  const GLuint zero_id[4] = {0, 0, 0, 0};
  const float far_depth = 1.0f;
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  for (GLint i = 0; i < 3; ++i) glClearNamedFramebufferfv(fb, GL_COLOR, i, &zero.x);
  glClearNamedFramebufferuiv(fb, GL_COLOR, 3, zero_id);
  glClearNamedFramebufferfv(fb, GL_DEPTH, 0, &far_depth);
  program_.set_uniform("write_motion", motion_ != nullptr ? 1 : 0);
  if (motion_ != nullptr) {
    glClearNamedFramebufferfv(fb, GL_COLOR, 4, &zero.x);
    motion_->bind_previous_vertices();
  }

  draw_scene_depth_tested(fb, targets_->width, targets_->height, program_, scene);
  check_gl("G-buffer pass");
}

}  // namespace glint::render
