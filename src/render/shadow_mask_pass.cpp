#include "render/shadow_mask_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

namespace glint::render {

ShadowMaskPass::ShadowMaskPass(const RasterTargets& targets)
    : targets_(&targets),
      draw_(targets.shadow_mask.id(), "shadow mask", "shadow_mask.frag.glsl") {
  check_gl("shadow mask pass set-up");
}

void ShadowMaskPass::run(const ShadowCubePass& cube, const RasterSettings& settings) {
  GlPassScope scope("shadow_mask");
  draw_.program().set_uniform("near_distance", cube.near_distance());
  draw_.program().set_uniform("texel_angle", 2.0f / static_cast<float>(cube.size()));
  draw_.program().set_uniform("pcf_radius_texels", settings.pcf_radius_texels);
  draw_.program().set_uniform("constant_bias_texels", settings.constant_bias_texels);
  draw_.program().set_uniform("slope_bias_texels", settings.slope_bias_texels);
  draw_.program().set_uniform("normal_offset_texels", settings.normal_offset_texels);

  glBindTextureUnit(0, targets_->world_position.id());
  glBindTextureUnit(1, targets_->world_normal_roughness.id());
  glBindTextureUnit(2, cube.cube_map());
  // PCF offsets near a face edge must read the neighbouring face, not clamp to this one.
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  draw_.draw(targets_->width, targets_->height);
  check_gl("shadow mask pass");
}

}  // namespace glint::render
