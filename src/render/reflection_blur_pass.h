#pragma once
// ReflectionBlurPass: the first half of the resolve. It fades the reflection image with the
// reflected ray's length and blurs it with a separable Gaussian in two compute dispatches
// (horizontal, then vertical), shaders/reflection_blur.comp.glsl. The blur is a normalised
// convolution over the pixels that found a reflection (a > 0): pixels without one neither darken
// their neighbours nor receive colour from them. docs/ssr.md has the formulas.
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/resolve_settings.h"

#include <epoxy/gl.h>

namespace glint::render {

class ReflectionBlurPass {
public:
  // Compiles the shader and creates the output and the intermediate image (both width x height).
  ReflectionBlurPass(int width, int height);
  void resize(int width, int height);

  // `reflection` is a kReflectionFormat texture of the pass's size (rgb colour, a = distance, 0 =
  // none). Uses settings.fade_start, fade_end and blur_radius (validated). blur_radius 0 runs one
  // dispatch that only fades. Ends with a memory barrier for any later read of output().
  void run(GLuint reflection, const ResolveSettings& settings);

  // kReflectionFormat: rgb = faded, blurred reflection (0 where the input's a is 0), a = the
  // input's distance at that pixel.
  GLuint output() const { return output_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }

private:
  ShaderProgram program_;
  int width_ = 0;
  int height_ = 0;
  GlTexture horizontal_;  // after the horizontal dispatch: rgb = normalised sum, a = coverage
  GlTexture output_;
};

// The fade factor the pass applies (1 - smoothstep(fade_start, fade_end, distance), or 1 when
// fade_end <= 0), on the CPU, for tests and documentation.
float reflection_fade(float distance, const ResolveSettings& settings);

}  // namespace glint::render
