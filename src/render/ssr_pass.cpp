#include "render/ssr_pass.h"

#include "gl/gl_check.h"
#include "render/compute_dispatch.h"
#include "gl/gl_pass_scope.h"
#include "render/frame_constants.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

#include <array>
#include <cstring>

namespace glint::render {
namespace {

// Image units, as declared in ssr.comp.glsl and ssr_colour.comp.glsl.
constexpr GLuint kAlbedoUnit = 0, kPositionUnit = 1, kNormalUnit = 2, kLitUnit = 3, kReflectionUnit = 4,
                 kFailureMaskUnit = 5, kHitUnit = 6;
constexpr GLuint kPyramidUnit = 0;  // texture unit of the depth pyramid (sampler depth_pyramid)

}  // namespace

SsrPass::SsrPass(int width, int height, const SsrSettings& settings)
    : program_(ShaderProgram::from_embedded({"ssr.comp.glsl"})),
      march_program_(ShaderProgram::from_embedded({"ssr_march.comp.glsl"})),
      colour_program_(ShaderProgram::from_embedded({"ssr_colour.comp.glsl"})),
      pyramid_(width, height),
      counts_readback_(kFramesInFlight, 2 * sizeof(std::uint32_t), "ssr counters") {
  set_settings(settings);
  counters_ = create_buffer(2 * sizeof(std::uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT);
  resize(width, height);
}

void SsrPass::resize(int width, int height) {
  require_pass_size("ssr", width, height);
  reflection_ = create_texture_2d(kReflectionFormat, width, height);
  failure_mask_ = create_texture_2d(kFailureMaskFormat, width, height);
  // The hits are made by the first march() (only frames that split SSR need them: 16 bytes a pixel).
  if (hits_.id() != 0) hits_ = create_texture_2d(kSsrHitFormat, width, height);
  if (pyramid_.width() != width || pyramid_.height() != height) pyramid_.resize(width, height);
  width_ = width;
  height_ = height;
  check_gl("ssr: create outputs");
}

void SsrPass::set_settings(const SsrSettings& settings) {
  validate(settings);
  settings_ = settings;
  for (ShaderProgram* program : {&program_, &march_program_}) {
    program->set_uniform("max_steps", settings.max_steps);
    program->set_uniform("thickness", settings.thickness);
    program->set_uniform("max_distance", settings.max_distance);
    program->set_uniform("confidence_threshold", settings.confidence_threshold);
    program->set_uniform("edge_fade", settings.edge_fade);
    program->set_uniform("min_hit_cosine", settings.min_hit_cosine);
    program->set_uniform("silhouette_footprints", settings.silhouette_footprints);
    program->set_uniform("max_screen_fraction", settings.max_screen_fraction);
    program->set_uniform("empty_behind", settings.empty_behind);
  }
}

void SsrPass::run(const SsrInputs& inputs) {
  GlPassScope scope("ssr");
  require_texture("ssr", "lit", inputs.lit, kLitFormat, width_, height_);
  dispatch_march(inputs, /*colour_in_march=*/true);
}

void SsrPass::march(const SsrInputs& inputs) {
  GlPassScope scope("ssr_march");
  dispatch_march(inputs, /*colour_in_march=*/false);
}

void SsrPass::dispatch_march(const SsrInputs& inputs, bool colour_in_march) {
  require_texture("ssr", "albedo_reflectivity", inputs.albedo_reflectivity, kAlbedoReflectivityFormat, width_,
                  height_);
  require_texture("ssr", "world_position", inputs.world_position, kWorldPositionFormat, width_, height_);
  require_texture("ssr", "world_normal", inputs.world_normal, kWorldNormalRoughnessFormat, width_, height_);
  require_buffer("ssr", "frame_constants", inputs.frame_constants);

  // The pyramid first: the trace reads it as a texture (unit kPyramidUnit).
  pyramid_.run({inputs.world_position, inputs.world_normal, inputs.frame_constants});

  const std::array<std::uint32_t, 2> zero{0, 0};
  glNamedBufferSubData(counters_.id(), 0, sizeof(zero), zero.data());

  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, inputs.frame_constants);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPixelCountersBinding, counters_.id());
  glBindImageTexture(kAlbedoUnit, inputs.albedo_reflectivity, 0, GL_FALSE, 0, GL_READ_ONLY, kAlbedoReflectivityFormat);
  glBindImageTexture(kPositionUnit, inputs.world_position, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(kNormalUnit, inputs.world_normal, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldNormalRoughnessFormat);
  // Bound either way (a declared image unit must hold an image of its format); read only with the colour.
  glBindImageTexture(kLitUnit, colour_in_march ? inputs.lit : reflection_.id(), 0, GL_FALSE, 0, GL_READ_ONLY,
                     kLitFormat);
  glBindImageTexture(kReflectionUnit, reflection_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kReflectionFormat);
  glBindImageTexture(kFailureMaskUnit, failure_mask_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kFailureMaskFormat);
  if (!colour_in_march) {
    if (hits_.id() == 0) hits_ = create_texture_2d(kSsrHitFormat, width_, height_);
    glBindImageTexture(kHitUnit, hits_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kSsrHitFormat);
  }
  glBindTextureUnit(kPyramidUnit, pyramid_.texture());
  ShaderProgram& program = colour_in_march ? program_ : march_program_;
  program.set_uniform("pyramid_levels", pyramid_.levels());
  dispatch_image_or_tiles(program, tiles_, width_, height_);
  // Later passes read the outputs as images or textures (the colour fetch the hits and distances,
  // the ray list the failure mask), the ray-trace step reads the counters as a buffer, and tests
  // read everything back.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
  check_gl("ssr: march");
}

void SsrPass::shade(const SsrInputs& inputs) {
  GlPassScope scope("ssr_colour");
  if (hits_.id() == 0) fail("ssr: shade() needs a march() first");
  require_texture("ssr", "world_position", inputs.world_position, kWorldPositionFormat, width_, height_);
  require_texture("ssr", "world_normal", inputs.world_normal, kWorldNormalRoughnessFormat, width_, height_);
  require_texture("ssr", "lit", inputs.lit, kLitFormat, width_, height_);
  require_buffer("ssr", "frame_constants", inputs.frame_constants);

  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, inputs.frame_constants);
  glBindImageTexture(kPositionUnit, inputs.world_position, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldPositionFormat);
  glBindImageTexture(kNormalUnit, inputs.world_normal, 0, GL_FALSE, 0, GL_READ_ONLY, kWorldNormalRoughnessFormat);
  glBindImageTexture(kLitUnit, inputs.lit, 0, GL_FALSE, 0, GL_READ_ONLY, kLitFormat);
  glBindImageTexture(kReflectionUnit, reflection_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, kReflectionFormat);
  glBindImageTexture(kHitUnit, hits_.id(), 0, GL_FALSE, 0, GL_READ_ONLY, kSsrHitFormat);
  dispatch_image_or_tiles(colour_program_, tiles_, width_, height_);
  // Hit shading and resolve read the reflection as an image or texture, tests read it back.
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("ssr: colour");
}

SsrCounts SsrPass::read_counts() const {
  std::array<std::uint32_t, 2> values{0, 0};
  glGetNamedBufferSubData(counters_.id(), 0, sizeof(values), values.data());
  check_gl("ssr: read counters");
  return {values[0], values[1]};
}

void SsrPass::request_counts(std::size_t slot) {
  counts_readback_.copy_buffer(slot, counters_.id(), 2 * sizeof(std::uint32_t));
}

std::optional<SsrCounts> SsrPass::requested_counts(std::size_t slot, bool wait) {
  const std::span<const std::byte> bytes = counts_readback_.read(slot, wait);
  if (bytes.empty()) return std::nullopt;
  std::array<std::uint32_t, 2> values{0, 0};
  std::memcpy(values.data(), bytes.data(), sizeof(values));
  return SsrCounts{values[0], values[1]};
}

}  // namespace glint::render
