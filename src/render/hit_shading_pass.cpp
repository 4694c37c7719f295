#include "render/hit_shading_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "render/compute_dispatch.h"
#include "gl/gl_pass_scope.h"
#include "render/frame_constants.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

namespace glint::render {
namespace {

constexpr GLuint kWorkGroupSize = 64;    // local_size_x in hit_shading.comp.glsl
constexpr GLuint kReflectionUnit = 0;    // image unit of the target
constexpr GLuint kShadowCubeUnit = 1;    // texture unit of the light's cube map (0 = material textures)
constexpr GLuint kNormalRoughnessUnit = 1;  // image unit of the G-buffer's normal + roughness

}  // namespace

HitShadingPass::HitShadingPass(int width, int height, RayHitBuffers& buffers)
    : program_(ShaderProgram::from_embedded({"hit_shading.comp.glsl"})), buffers_(&buffers), width_(width),
      height_(height) {
  require_pass_size("hit shading", width, height);
  program_.set_uniform("miss_distance", kMissDistance);
  check_gl("hit shading: set-up");
}

void HitShadingPass::run(const HitShadingInputs& inputs, std::uint32_t max_rays) {
  GlPassScope scope("hit_shade");
  if (inputs.scene == nullptr || inputs.shadow_cube == nullptr || inputs.raster == nullptr)
    fail("hit shading: scene, shadow cube and raster settings are required inputs");
  require_texture("hit shading", "reflection", inputs.reflection, kReflectionFormat, width_, height_);
  require_buffer("hit shading", "frame_constants", inputs.frame_constants);
  if (inputs.world_normal_roughness != 0)
    require_texture("hit shading", "world_normal_roughness", inputs.world_normal_roughness, kWorldNormalRoughnessFormat,
                    width_, height_);
  if (max_rays > buffers_->capacity())
    fail("hit shading: {} rays, more than the ray buffers' capacity {}", max_rays, buffers_->capacity());
  if (max_rays == 0) return;

  const ShadowCubePass& cube = *inputs.shadow_cube;
  const RasterSettings& raster = *inputs.raster;
  set_cube_shadow_uniforms(program_, cube, raster);
  program_.set_uniform("ambient_fraction", raster.ambient_fraction);
  program_.set_uniform("texture_layer_size", static_cast<float>(inputs.scene->texture_layer_size()));
  program_.set_uniform("shadow_from_rays", inputs.shadow_answers != nullptr ? 1 : 0);
  if (inputs.shadow_answers != nullptr) {
    program_.set_uniform("occlusion_flag_bytes", inputs.shadow_answers->flag_bytes());
    inputs.shadow_answers->bind();
  }

  inputs.scene->bind_resources();
  buffers_->bind();
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, inputs.frame_constants);
  glBindTextureUnit(kShadowCubeUnit, cube.cube_map());
  glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
  glBindImageTexture(kReflectionUnit, inputs.reflection, 0, GL_FALSE, 0, GL_READ_WRITE, kReflectionFormat);
  program_.set_uniform("glossy_weight", inputs.world_normal_roughness != 0 ? 1 : 0);
  if (inputs.world_normal_roughness != 0)
    glBindImageTexture(kNormalRoughnessUnit, inputs.world_normal_roughness, 0, GL_FALSE, 0, GL_READ_ONLY,
                       kWorldNormalRoughnessFormat);
  program_.use();
  glDispatchCompute(work_groups(max_rays, kWorkGroupSize), 1, 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("hit shading");
}

}  // namespace glint::render
