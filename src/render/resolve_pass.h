#pragma once
// ResolvePass: the last step of a frame's reflections. It fades and blurs the reflection image
// (ReflectionBlurPass; with ResolveSettings::denoise the ReflectionDenoiser instead, docs/glossy.md),
// then composites in shaders/resolve.comp.glsl:
//   final = srgb_encode(tone_map(exposure * (lit + reflectivity * reflection_faded_blurred)))
// into a kFinalFormat (RGBA8, sRGB-encoded, a = 1) image. docs/ssr.md has the formulas.
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "core/math.h"
#include "render/reflection_blur_pass.h"
#include "render/reflection_denoiser.h"
#include "render/resolve_settings.h"

#include <epoxy/gl.h>

#include <optional>

namespace glint::render {

// Inputs, all width x height in the formats of render_targets.h.
struct ResolveInputs {
  GLuint lit = 0;                  // kLitFormat
  GLuint albedo_reflectivity = 0;  // kAlbedoReflectivityFormat; a = reflectivity
  GLuint reflection = 0;           // kReflectionFormat (SSR hits, later merged with ray-traced ones)
  // Only with denoise (the denoiser's guides and reprojection):
  GLuint world_position = 0;          // kWorldPositionFormat
  GLuint world_normal_roughness = 0;  // kWorldNormalRoughnessFormat
  GLuint frame_constants = 0;         // FrameConstants uniform buffer
  mat4 view_projection{1.0f};         // this frame's camera
};

class ResolvePass {
public:
  // Compiles the shaders and creates the outputs; throws glint::Error for a non-positive size or
  // invalid settings.
  ResolvePass(int width, int height, const ResolveSettings& settings = {});

  void resize(int width, int height);
  void set_settings(const ResolveSettings& settings);  // validated; throws glint::Error
  const ResolveSettings& settings() const { return settings_; }

  // Fade + blur, then composite. Inputs are checked (ids, sizes, formats). Ends with a memory
  // barrier for any later read of the outputs.
  void run(const ResolveInputs& inputs);

  // Debug view: the faded, blurred (or denoised) reflection (RGBA16F, see ReflectionBlurPass::output()
  // and ReflectionDenoiser::output()).
  GLuint blurred_reflection() const { return denoiser_ && settings_.denoise ? denoiser_->output() : blur_.output(); }
  // The denoiser (with denoise, after the first run), for tests and debug views; null otherwise.
  const ReflectionDenoiser* denoiser() const { return denoiser_ ? &*denoiser_ : nullptr; }
  // The frame: kFinalFormat, sRGB-encoded, a = 1.
  GLuint final_image() const { return final_.id(); }
  int width() const { return blur_.width(); }
  int height() const { return blur_.height(); }

private:
  ReflectionBlurPass blur_;
  std::optional<ReflectionDenoiser> denoiser_;  // created by the first run with denoise
  ShaderProgram program_;
  ResolveSettings settings_;
  GlTexture final_;
};

}  // namespace glint::render
