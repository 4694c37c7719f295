#include "render/depth_pyramid_pass.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/frame_constants.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

#include <algorithm>

namespace glint::render {
namespace {

// Dispatch 1 builds levels 0..kTileLevel (depth_pyramid_tiles.comp.glsl's kMaxTileLevel): with the
// two G-buffer inputs, that is the 8 image units GL guarantees a compute shader (and the tail's
// array of levels is that size too).
constexpr int kTileLevel = 5;
constexpr int kTailImageUnits = 8;

}  // namespace

DepthPyramidPass::DepthPyramidPass(int width, int height)
    : tiles_(ShaderProgram::from_embedded({"depth_pyramid_tiles.comp.glsl"})),
      tail_(ShaderProgram::from_embedded({"depth_pyramid_tail.comp.glsl"})) {
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
  // Units 2..7: levels 0..kTileLevel, those past the last level bound to it (and not written).
  const int tile_level = std::min(kTileLevel, levels_ - 1);
  for (int level = 0; level <= kTileLevel; ++level) {
    glBindImageTexture(static_cast<GLuint>(2 + level), pyramid_.id(), std::min(level, levels_ - 1), GL_FALSE, 0,
                       GL_WRITE_ONLY, kDepthPyramidFormat);
  }
  tiles_.set_uniform("tile_level", tile_level);
  tiles_.use();
  glDispatchCompute(static_cast<GLuint>(std::max(1, width_ >> tile_level)),
                    static_cast<GLuint>(std::max(1, height_ >> tile_level)), 1);

  // The tail: kTailImageUnits levels bound a dispatch, the first the level below those it builds.
  // One dispatch for images up to 8191 pixels a side (13 levels).
  tail_.use();
  for (int first = tile_level + 1; first < levels_; first += kTailImageUnits - 1) {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    for (int unit = 0; unit < kTailImageUnits; ++unit) {
      glBindImageTexture(static_cast<GLuint>(unit), pyramid_.id(), std::min(first - 1 + unit, levels_ - 1), GL_FALSE,
                         0, GL_READ_WRITE, kDepthPyramidFormat);
    }
    tail_.set_uniform("level_count", std::min(kTailImageUnits - 1, levels_ - first));
    glDispatchCompute(1, 1, 1);
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("depth pyramid");
}

}  // namespace glint::render
