#include "render/lighting_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

namespace glint::render {

LightingPass::LightingPass(const RasterTargets& targets)
    : targets_(&targets),
      draw_(targets.lit.id(), "lit image", "lighting.frag.glsl") {
  check_gl("lighting pass set-up");
}

void LightingPass::run(const GpuScene& scene, const RasterSettings& settings) {
  GlPassScope scope("light");
  draw_.program().set_uniform("ambient_fraction", settings.ambient_fraction);
  scene.bind_resources();  // the materials buffer
  glBindTextureUnit(0, targets_->albedo_reflectivity.id());
  glBindTextureUnit(1, targets_->world_position.id());
  glBindTextureUnit(2, targets_->world_normal_roughness.id());
  glBindTextureUnit(3, targets_->material_id.id());
  glBindTextureUnit(4, targets_->shadow_mask.id());
  draw_.draw(targets_->width, targets_->height);
  check_gl("lighting pass");
}

}  // namespace glint::render
