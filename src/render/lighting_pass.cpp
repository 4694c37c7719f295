#include "render/lighting_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/render_targets.h"

namespace glint::render {
namespace {

// Texture units and the image unit of lighting.comp.glsl.
constexpr GLuint kAlbedoUnit = 0, kPositionUnit = 1, kNormalUnit = 2, kMaterialIdUnit = 3, kShadowMaskUnit = 4;
constexpr GLuint kLitImageUnit = 0;

}  // namespace

LightingPass::LightingPass(const RasterTargets& targets)
    : targets_(&targets), program_(ShaderProgram::from_embedded({"lighting.comp.glsl"})) {
  check_gl("lighting pass set-up");
}

void LightingPass::run(const GpuScene& scene, const RasterSettings& settings) {
  GlPassScope scope("light");
  program_.set_uniform("ambient_fraction", settings.ambient_fraction);
  scene.bind_resources();  // the materials buffer
  glBindTextureUnit(kAlbedoUnit, targets_->albedo_reflectivity.id());
  glBindTextureUnit(kPositionUnit, targets_->world_position.id());
  glBindTextureUnit(kNormalUnit, targets_->world_normal_roughness.id());
  glBindTextureUnit(kMaterialIdUnit, targets_->material_id.id());
  glBindTextureUnit(kShadowMaskUnit, targets_->shadow_mask.id());
  glBindImageTexture(kLitImageUnit, targets_->lit.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kLitFormat);
  program_.use();
  dispatch_over_image(targets_->width, targets_->height);
  // Readers of lit: SSR and the resolve load it as an image, debug views and tests read it back,
  // and it may be fetched as a texture or copied through a framebuffer.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("lighting pass");
}

}  // namespace glint::render
