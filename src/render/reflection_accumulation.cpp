#include "render/reflection_accumulation.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "render/compute_dispatch.h"
#include "render/reflection_texture_check.h"
#include "render/render_targets.h"

namespace glint::render {

ReflectionAccumulation::ReflectionAccumulation(int width, int height)
    : program_(ShaderProgram::from_embedded({"reflection_accumulate.comp.glsl"})), width_(width), height_(height) {
  require_pass_size("reflection accumulation", width, height);
  sum_ = create_texture_2d(GL_RGBA32F, width, height);
  hits_ = create_texture_2d(GL_R32F, width, height);
  check_gl("reflection accumulation: set-up");
}

void ReflectionAccumulation::add(GLuint reflection, int sample_index, int samples) {
  require_texture("reflection accumulation", "reflection", reflection, kReflectionFormat, width_, height_);
  if (samples < 1 || sample_index < 0 || sample_index >= samples)
    fail("reflection accumulation: sample {} of {}", sample_index, samples);
  program_.set_uniform("sample_index", sample_index);
  program_.set_uniform("samples", samples);
  glBindImageTexture(0, reflection, 0, GL_FALSE, 0, GL_READ_WRITE, kReflectionFormat);
  glBindImageTexture(1, sum_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
  glBindImageTexture(2, hits_.id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
  program_.use();
  dispatch_over_image(width_, height_);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
  check_gl("reflection accumulation");
}

}  // namespace glint::render
