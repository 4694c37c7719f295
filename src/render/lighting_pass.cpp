#include "render/lighting_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

namespace glint::render {

LightingPass::LightingPass(const RasterTargets& targets)
    : targets_(&targets),
      framebuffer_(create_framebuffer()),
      empty_vertex_array_(create_vertex_array()),
      program_(ShaderProgram::from_embedded({"fullscreen.vert.glsl", "lighting.frag.glsl"})) {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, targets.lit.id(), 0);
  require_framebuffer_complete(framebuffer_, "lit image");
  check_gl("lighting pass set-up");
}

void LightingPass::run(const GpuScene& scene, const RasterSettings& settings) {
  GlPassScope scope("light");
  program_.set_uniform("ambient_fraction", settings.ambient_fraction);
  scene.bind_resources();  // the materials buffer
  glBindTextureUnit(0, targets_->albedo_reflectivity.id());
  glBindTextureUnit(1, targets_->world_position.id());
  glBindTextureUnit(2, targets_->world_normal_roughness.id());
  glBindTextureUnit(3, targets_->material_id.id());
  glBindTextureUnit(4, targets_->shadow_mask.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, targets_->width, targets_->height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  program_.use();
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  check_gl("lighting pass");
}

}  // namespace glint::render
