#pragma once
// ReflectionAccumulation: the mean of a frame's reflection samples (--spp N, docs/glossy.md). The
// frame pipeline runs SSR and the ray-traced complement once per sample into the same reflection
// image and calls add() after each; the last add() leaves the mean in that image (rgb averaged over
// all N samples, a sample without a reflection counting as black; a = the mean distance of the
// samples that found one), so the resolve reads it as it reads a one-sample image.
//   shaders/reflection_accumulate.comp.glsl
#include "gl/gl_objects.h"
#include "gl/shader_program.h"

#include <epoxy/gl.h>

namespace glint::render {

class ReflectionAccumulation {
public:
  // Throws glint::Error for a non-positive size.
  ReflectionAccumulation(int width, int height);

  // Adds sample `sample_index` (0 .. samples - 1) of `reflection` (kReflectionFormat, width x
  // height); the last one writes the mean into `reflection`. Ends with an image barrier.
  void add(GLuint reflection, int sample_index, int samples);

private:
  ShaderProgram program_;
  int width_, height_;
  GlTexture sum_;   // RGBA32F: rgb, distance
  GlTexture hits_;  // R32F
};

}  // namespace glint::render
