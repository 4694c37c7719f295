#include "render/resolve_pass.h"

#include "gl/gl_check.h"
#include "render/compute_dispatch.h"
#include "gl/gl_pass_scope.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

namespace glint::render {
namespace {

// Image units of resolve.comp.glsl.
constexpr GLuint kLitUnit = 0, kAlbedoUnit = 1, kReflectionUnit = 2, kFinalUnit = 3, kLinearUnit = 4;

}  // namespace

ResolvePass::ResolvePass(int width, int height, const ResolveSettings& settings)
    : blur_(width, height), program_(ShaderProgram::from_embedded({"resolve.comp.glsl"})) {
  set_settings(settings);
  resize(width, height);
}

void ResolvePass::resize(int width, int height) {
  require_pass_size("resolve", width, height);
  if (width != blur_.width() || height != blur_.height()) {
    blur_.resize(width, height);
    denoiser_.reset();
  }
  final_ = create_texture_2d(kFinalFormat, width, height);
  if (linear_.id() != 0) linear_ = create_texture_2d(kLinearColourFormat, width, height);
  check_gl("resolve: create final image");
}

void ResolvePass::set_linear_output(bool on) {
  if (on == (linear_.id() != 0)) return;
  linear_ = on ? create_texture_2d(kLinearColourFormat, width(), height()) : GlTexture();
  program_.set_uniform("store_linear", on ? 1 : 0);
  check_gl("resolve: create linear image");
}

void ResolvePass::set_settings(const ResolveSettings& settings) {
  validate(settings);
  settings_ = settings;
  program_.set_uniform("exposure", settings.exposure);
  program_.set_uniform("tone_map", static_cast<int>(settings.tone_map));
}

void ResolvePass::run(const ResolveInputs& inputs) {
  GlPassScope scope("resolve");
  const int w = width(), h = height();
  require_texture("resolve", "lit", inputs.lit, kLitFormat, w, h);
  require_texture("resolve", "albedo_reflectivity", inputs.albedo_reflectivity, kAlbedoReflectivityFormat, w, h);
  require_texture("resolve", "reflection", inputs.reflection, kReflectionFormat, w, h);

  GLuint filtered = 0;
  if (settings_.denoise) {
    if (!denoiser_) denoiser_.emplace(w, h);
    denoiser_->run({inputs.reflection, inputs.world_position, inputs.world_normal_roughness, inputs.albedo_reflectivity,
                    inputs.frame_constants, inputs.view_projection, inputs.world_motion},
                   settings_);
    filtered = denoiser_->output();
  } else {
    blur_.run(inputs.reflection, settings_);
    filtered = blur_.output();
  }

  glBindImageTexture(kLitUnit, inputs.lit, 0, GL_FALSE, 0, GL_READ_ONLY, kLitFormat);
  glBindImageTexture(kAlbedoUnit, inputs.albedo_reflectivity, 0, GL_FALSE, 0, GL_READ_ONLY, kAlbedoReflectivityFormat);
  glBindImageTexture(kReflectionUnit, filtered, 0, GL_FALSE, 0, GL_READ_ONLY, kReflectionFormat);
  glBindImageTexture(kFinalUnit, final_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kFinalFormat);
  if (linear_.id() != 0)
    glBindImageTexture(kLinearUnit, linear_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, kLinearColourFormat);
  program_.use();
  dispatch_over_image(w, h);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_FRAMEBUFFER_BARRIER_BIT);
  check_gl("resolve");
}

}  // namespace glint::render
