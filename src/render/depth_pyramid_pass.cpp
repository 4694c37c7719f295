#include "render/depth_pyramid_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/frame_constants.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

#include <algorithm>

namespace glint::render {

DepthPyramidPass::DepthPyramidPass(int width, int height)
    : base_(ShaderProgram::from_embedded({"depth_pyramid_base.comp.glsl"})),
      reduce_(ShaderProgram::from_embedded({"depth_pyramid_reduce.comp.glsl"})) {
  resize(width, height);
}

int DepthPyramidPass::level_count(int width, int height) {
  int levels = 1;
  for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
  return levels;
}

void DepthPyramidPass::resize(int width, int height) {
  require_pass_size("depth pyramid", width, height);
  levels_ = level_count(width, height);
  pyramid_ = create_texture_2d(kDepthPyramidFormat, width, height, levels_);
  // The trace reads exact texels with texelFetch; no filtering anywhere.
  glTextureParameteri(pyramid_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTextureParameteri(pyramid_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  width_ = width;
  height_ = height;
  check_gl("depth pyramid: create texture");
}

void DepthPyramidPass::run(const DepthPyramidInputs& inputs) {
  GlPassScope scope("depth_pyramid");
  require_texture("depth pyramid", "world_position", inputs.world_position, kWorldPositionFormat, width_, height_);
  require_texture("depth pyramid", "world_normal", inputs.world_normal, kWorldNormalRoughnessFormat, width_,
                  height_);
  require_buffer("depth pyramid", "frame_constants", inputs.frame_constants);

  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, inputs.frame_constants);
  glBindImageTexture(0, inputs.world_position, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(1, inputs.world_normal, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldNormalRoughnessFormat);
  glBindImageTexture(2, pyramid_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kDepthPyramidFormat);
  base_.use();
  dispatch_over_image(width_, height_);

  reduce_.use();
  for (int level = 1; level < levels_; ++level) {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    glBindImageTexture(0, pyramid_.id(), level - 1, GL_FALSE, 0, GL_READ_ONLY, kDepthPyramidFormat);
    glBindImageTexture(1, pyramid_.id(), level, GL_FALSE, 0, GL_WRITE_ONLY, kDepthPyramidFormat);
    dispatch_over_image(std::max(1, width_ >> level), std::max(1, height_ >> level));
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("depth pyramid");
}

}  // namespace glint::render
