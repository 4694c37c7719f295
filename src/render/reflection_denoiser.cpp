#include "render/reflection_denoiser.h"

#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "render/compute_dispatch.h"
#include "render/frame_constants.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"
#include "render/surface_motion.h"

#include <cstddef>

namespace glint::render {
namespace {

constexpr GLenum kHistoryFormat = GL_RGBA16F;
constexpr GLuint kMotionBinding = 24;  // storage binding of the motion buffer (reflection_temporal.comp.glsl)

void copy_texture(GLuint from, GLuint to, int width, int height) {
  glCopyImageSubData(from, GL_TEXTURE_2D, 0, 0, 0, 0, to, GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
}

}  // namespace

ReflectionDenoiser::ReflectionDenoiser(int width, int height)
    : temporal_(ShaderProgram::from_embedded({"reflection_temporal.comp.glsl"})),
      spatial_(ShaderProgram::from_embedded({"reflection_spatial.comp.glsl"})),
      width_(width),
      height_(height) {
  require_pass_size("reflection denoiser", width, height);
  for (int i = 0; i < 2; ++i) {
    history_[i] = create_texture_2d(kHistoryFormat, width, height);
    filtered_[i] = create_texture_2d(kHistoryFormat, width, height);
  }
  previous_position_ = create_texture_2d(kWorldPositionFormat, width, height);
  previous_normal_ = create_texture_2d(kWorldNormalRoughnessFormat, width, height);
  motion_ = create_buffer(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * sizeof(vec2), nullptr,
                          GL_DYNAMIC_STORAGE_BIT);
  check_gl("reflection denoiser: set-up");
}

void ReflectionDenoiser::run(const DenoiserInputs& inputs, const ResolveSettings& settings) {
  GlPassScope scope("denoise");
  const int w = width_, h = height_;
  require_texture("reflection denoiser", "reflection", inputs.reflection, kReflectionFormat, w, h);
  require_texture("reflection denoiser", "world_position", inputs.world_position, kWorldPositionFormat, w, h);
  require_texture("reflection denoiser", "world_normal_roughness", inputs.world_normal_roughness,
                  kWorldNormalRoughnessFormat, w, h);
  require_texture("reflection denoiser", "albedo_reflectivity", inputs.albedo_reflectivity, kAlbedoReflectivityFormat,
                  w, h);
  require_buffer("reflection denoiser", "frame_constants", inputs.frame_constants);
  if (inputs.world_motion != 0)
    require_texture("reflection denoiser", "world_motion", inputs.world_motion, kWorldMotionFormat, w, h);
  const DenoiseSettings& d = settings.denoiser;
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, inputs.frame_constants);

  // Temporal: history_[current_ ^ 1] (last frame's) -> history_[current_].
  temporal_.set_uniform("previous_view_projection", previous_view_projection_);
  temporal_.set_uniform("has_history", has_history_ ? 1 : 0);
  temporal_.set_uniform("max_history", d.max_history);
  temporal_.set_uniform("clamp_sigma", d.clamp_sigma);
  temporal_.set_uniform("depth_tolerance", d.depth_tolerance);
  temporal_.set_uniform("fade_start", settings.fade_start);
  temporal_.set_uniform("fade_end", settings.fade_end);
  temporal_.set_uniform("has_motion", inputs.world_motion != 0 ? 1 : 0);
  glBindTextureUnit(0, inputs.reflection);
  glBindTextureUnit(1, inputs.world_position);
  glBindTextureUnit(2, inputs.world_normal_roughness);
  glBindTextureUnit(3, inputs.albedo_reflectivity);
  glBindTextureUnit(4, history_[current_ ^ 1].id());
  glBindTextureUnit(5, previous_position_.id());
  glBindTextureUnit(6, previous_normal_.id());
  glBindTextureUnit(7, inputs.world_motion);
  glBindImageTexture(0, history_[current_].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kHistoryFormat);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMotionBinding, motion_.id());
  temporal_.use();
  dispatch_over_image(w, h);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);

  // Spatial: a-trous iterations, ping-pong through filtered_.
  spatial_.set_uniform("max_sigma", d.max_sigma);
  spatial_.set_uniform("depth_sigma", d.depth_sigma);
  spatial_.set_uniform("normal_power", d.normal_power);
  spatial_.set_uniform("roughness_sigma", d.roughness_sigma);
  GLuint source = history_[current_].id();
  for (int i = 0; i < d.iterations; ++i) {
    const int target = i % 2;
    spatial_.set_uniform("step", 1 << i);
    glBindTextureUnit(0, source);
    glBindImageTexture(0, filtered_[target].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kHistoryFormat);
    spatial_.use();
    dispatch_over_image(w, h);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    source = filtered_[target].id();
    last_output_ = target;
  }

  // This frame becomes the next one's history.
  copy_texture(inputs.world_position, previous_position_.id(), w, h);
  copy_texture(inputs.world_normal_roughness, previous_normal_.id(), w, h);
  previous_view_projection_ = inputs.view_projection;
  has_history_ = true;
  current_ ^= 1;
  for (GLuint unit = 0; unit < 8; ++unit) glBindTextureUnit(unit, 0);
  check_gl("reflection denoiser");
}

std::vector<vec2> ReflectionDenoiser::read_motion() const {
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<vec2> motion(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
  glGetNamedBufferSubData(motion_.id(), 0, static_cast<GLsizeiptr>(motion.size() * sizeof(vec2)), motion.data());
  check_gl("reflection denoiser: motion readback");
  return motion;
}

}  // namespace glint::render
