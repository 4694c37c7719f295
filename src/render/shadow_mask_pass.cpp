#include "render/shadow_mask_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/render_targets.h"

namespace glint::render {
namespace {

// Texture units and the image unit of shadow_mask.comp.glsl.
constexpr GLuint kPositionUnit = 0, kNormalUnit = 1, kCubeUnit = 2;
constexpr GLuint kMaskImageUnit = 0;

}  // namespace

ShadowMaskPass::ShadowMaskPass(const RasterTargets& targets)
    : targets_(&targets), program_(ShaderProgram::from_embedded({"shadow_mask.comp.glsl"})) {
  check_gl("shadow mask pass set-up");
}

void ShadowMaskPass::run(const ShadowCubePass& cube, const RasterSettings& settings) {
  GlPassScope scope("shadow_mask");
  program_.set_uniform("near_distance", cube.near_distance());
  program_.set_uniform("texel_angle", 2.0f / static_cast<float>(cube.size()));
  program_.set_uniform("pcf_radius_texels", settings.pcf_radius_texels);
  program_.set_uniform("constant_bias_texels", settings.constant_bias_texels);
  program_.set_uniform("slope_bias_texels", settings.slope_bias_texels);
  program_.set_uniform("normal_offset_texels", settings.normal_offset_texels);

  glBindTextureUnit(kPositionUnit, targets_->world_position.id());
  glBindTextureUnit(kNormalUnit, targets_->world_normal_roughness.id());
  glBindTextureUnit(kCubeUnit, cube.cube_map());
  // PCF offsets near a face edge must read the neighbouring face, not clamp to this one.
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glBindImageTexture(kMaskImageUnit, targets_->shadow_mask.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kShadowMaskFormat);
  program_.use();
  dispatch_over_image(targets_->width, targets_->height);
  // Readers of the mask: lighting and the shadow-ray pass (texture fetches, image loads), read-backs.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("shadow mask pass");
}

}  // namespace glint::render
