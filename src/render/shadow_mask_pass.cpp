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
  set_cube_shadow_uniforms(program_, cube, settings);

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
