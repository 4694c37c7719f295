#include "render/reflection_sampling.h"

#include "core/error.h"
#include "core/math.h"
#include "render/frame_constants.h"

#include <cmath>
#include <cstddef>

namespace glint::render {

void validate(const ReflectionSamplingSettings& s) {
  if (s.samples_per_pixel < 1 || s.samples_per_pixel > 4096)
    fail("reflection sampling: samples per pixel {} is outside 1..4096", s.samples_per_pixel);
  if (!(s.roughness_cutoff >= 0.0f && s.roughness_cutoff <= 1.0f))
    fail("reflection sampling: roughness cutoff {} is outside 0..1", s.roughness_cutoff);
}

void write_reflection_sampling(GLuint frame_constants, const ReflectionSamplingSettings& settings, int sample_index) {
  const vec4 value(settings.roughness_cutoff, static_cast<float>(sample_index),
                   static_cast<float>(settings.samples_per_pixel), settings.glossy ? 1.0f : 0.0f);
  glNamedBufferSubData(frame_constants, static_cast<GLintptr>(offsetof(FrameConstants, reflection_sampling)),
                       sizeof(value), &value);
}

}  // namespace glint::render
