#include "render/ray_list_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "render/compute_dispatch.h"
#include "gl/gl_pass_scope.h"
#include "render/frame_constants.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace glint::render {
namespace {

constexpr GLuint kAlbedoUnit = 0, kPositionUnit = 1, kNormalUnit = 2, kFailureMaskUnit = 3;

}  // namespace

RayListPass::RayListPass(int width, int height, RayHitBuffers& buffers)
    : program_(ShaderProgram::from_embedded({"ray_list.comp.glsl"})),
      clamp_program_(ShaderProgram::from_embedded({"ray_budget_clamp.comp.glsl"})),
      buffers_(&buffers),
      width_(width),
      height_(height) {
  require_pass_size("ray list", width, height);
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  if (buffers.capacity() < pixels)
    fail("ray list: the ray buffers hold {} rays, a {}x{} frame may need {}", buffers.capacity(), width, height,
         pixels);
  no_failure_mask_ = create_texture_2d(kFailureMaskFormat, 1, 1);
  set_origin_offset(0.0f);
  check_gl("ray list: set-up");
}

std::uint32_t RayListPass::capacity_limit() const {
  return static_cast<std::uint32_t>(std::min<std::size_t>(buffers_->capacity(), 0x7fffffffu));
}

void RayListPass::set_origin_offset(float offset) {
  if (!(offset >= 0.0f) || !std::isfinite(offset)) fail("ray list: origin offset {} must be finite and >= 0", offset);
  program_.set_uniform("origin_offset", offset);
}

void RayListPass::run(const RayListInputs& inputs) {
  GlPassScope scope("ray_list");
  require_texture("ray list", "albedo_reflectivity", inputs.albedo_reflectivity, kAlbedoReflectivityFormat, width_,
                  height_);
  require_texture("ray list", "world_position", inputs.world_position, kWorldPositionFormat, width_, height_);
  require_texture("ray list", "world_normal", inputs.world_normal, kWorldNormalRoughnessFormat, width_, height_);
  const bool trace_all = inputs.failure_mask == 0;
  if (!trace_all)
    require_texture("ray list", "failure_mask", inputs.failure_mask, kFailureMaskFormat, width_, height_);
  require_buffer("ray list", "frame_constants", inputs.frame_constants);

  buffers_->reset_counters();
  buffers_->bind();
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, inputs.frame_constants);
  glBindImageTexture(kAlbedoUnit, inputs.albedo_reflectivity, 0, GL_FALSE, 0, GL_READ_ONLY, kAlbedoReflectivityFormat);
  glBindImageTexture(kPositionUnit, inputs.world_position, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(kNormalUnit, inputs.world_normal, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldNormalRoughnessFormat);
  glBindImageTexture(kFailureMaskUnit, trace_all ? no_failure_mask_.id() : inputs.failure_mask, 0, GL_FALSE, 0,
                     GL_READ_ONLY, kFailureMaskFormat);
  program_.set_uniform("trace_all", trace_all ? 1 : 0);
  const std::uint32_t max_rays = tiles_ ? std::min<std::uint32_t>(tiles_->max_rays, capacity_limit()) : capacity_limit();
  program_.set_uniform("max_rays", static_cast<int>(max_rays));
  dispatch_image_or_tiles(program_, tiles_ ? std::optional(tiles_->tiles) : std::nullopt, width_, height_);
  // Hit shading reads the pixel list as a storage buffer; the CPU's view is made visible by
  // RayHitBuffers::finish_ray_list().
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  if (tiles_) {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kTileDispatchBinding, tiles_->tiles.dispatch_buffer);
    clamp_program_.set_uniform("max_rays", static_cast<int>(max_rays));
    clamp_program_.use();
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  }
  check_gl("ray list");
}

}  // namespace glint::render
