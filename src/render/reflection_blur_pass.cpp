#include "render/reflection_blur_pass.h"

#include "gl/gl_check.h"
#include "render/compute_dispatch.h"
#include "gl/gl_pass_scope.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

#include <algorithm>

namespace glint::render {
namespace {

// `mode` values of the shader.
constexpr int kFadeOnly = 0, kHorizontal = 1, kVertical = 2;
// Image units of the shader.
constexpr GLuint kSourceUnit = 0, kTargetUnit = 1, kOriginalUnit = 2;

}  // namespace

float reflection_fade(float distance, const ResolveSettings& settings) {
  if (settings.fade_end <= 0.0f) return 1.0f;
  const float x = std::clamp((distance - settings.fade_start) / (settings.fade_end - settings.fade_start), 0.0f, 1.0f);
  return 1.0f - x * x * (3.0f - 2.0f * x);
}

ReflectionBlurPass::ReflectionBlurPass(int width, int height)
    : program_(ShaderProgram::from_embedded({"reflection_blur.comp.glsl"})) {
  resize(width, height);
}

void ReflectionBlurPass::resize(int width, int height) {
  require_pass_size("reflection blur", width, height);
  horizontal_ = create_texture_2d(kReflectionFormat, width, height);
  output_ = create_texture_2d(kReflectionFormat, width, height);
  width_ = width;
  height_ = height;
  check_gl("reflection blur: create images");
}

void ReflectionBlurPass::run(GLuint reflection, const ResolveSettings& settings) {
  GlPassScope scope("reflection blur");
  validate(settings);
  require_texture("reflection blur", "reflection", reflection, kReflectionFormat, width_, height_);
  program_.set_uniform("fade_start", settings.fade_start);
  program_.set_uniform("fade_end", settings.fade_end);
  program_.set_uniform("radius", settings.blur_radius);
  program_.set_uniform("sigma", 0.5f * static_cast<float>(settings.blur_radius));
  program_.use();

  const auto dispatch = [&](int mode, GLuint source, GLuint target) {
    program_.set_uniform("mode", mode);
    glBindImageTexture(kSourceUnit, source, 0, GL_FALSE, 0, GL_READ_ONLY, kReflectionFormat);
    glBindImageTexture(kTargetUnit, target, 0, GL_FALSE, 0, GL_WRITE_ONLY, kReflectionFormat);
    glBindImageTexture(kOriginalUnit, reflection, 0, GL_FALSE, 0, GL_READ_ONLY, kReflectionFormat);
    dispatch_over_image(width_, height_);
  };
  if (settings.blur_radius == 0) {
    dispatch(kFadeOnly, reflection, output_.id());
  } else {
    dispatch(kHorizontal, reflection, horizontal_.id());
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);  // the vertical dispatch loads what it stored
    dispatch(kVertical, horizontal_.id(), output_.id());
  }
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("reflection blur");
}

}  // namespace glint::render
