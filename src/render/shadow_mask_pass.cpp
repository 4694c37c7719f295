#include "render/shadow_mask_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

namespace glint::render {

ShadowMaskPass::ShadowMaskPass(const RasterTargets& targets)
    : targets_(&targets),
      framebuffer_(create_framebuffer()),
      empty_vertex_array_(create_vertex_array()),
      program_(ShaderProgram::from_embedded({"fullscreen.vert.glsl", "shadow_mask.frag.glsl"})) {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, targets.shadow_mask.id(), 0);
  require_framebuffer_complete(framebuffer_, "shadow mask");
  check_gl("shadow mask pass set-up");
}

void ShadowMaskPass::run(const ShadowCubePass& cube, const RasterSettings& settings) {
  GlPassScope scope("shadow_mask");
  program_.set_uniform("far_distance", cube.far_distance());
  program_.set_uniform("texel_angle", 2.0f / static_cast<float>(cube.size()));
  program_.set_uniform("pcf_radius_texels", settings.pcf_radius_texels);
  program_.set_uniform("constant_bias_texels", settings.constant_bias_texels);
  program_.set_uniform("slope_bias_texels", settings.slope_bias_texels);
  program_.set_uniform("normal_offset_texels", settings.normal_offset_texels);

  glBindTextureUnit(0, targets_->world_position.id());
  glBindTextureUnit(1, targets_->world_normal_roughness.id());
  glBindTextureUnit(2, cube.cube_map());
  // PCF offsets near a face edge must read the neighbouring face, not clamp to this one.
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, targets_->width, targets_->height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  program_.use();
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  check_gl("shadow mask pass");
}

}  // namespace glint::render
