#pragma once
// ResolvePass: the last step of a frame's reflections. It fades and blurs the reflection image
// (ReflectionBlurPass; with ResolveSettings::denoise the ReflectionDenoiser instead, docs/glossy.md),
// then composites in shaders/resolve.comp.glsl:
//   final = srgb_encode(tone_map(exposure * (lit + reflectivity * reflection_faded_blurred)))
// into a kFinalFormat (RGBA8, sRGB-encoded, a = 1) image. docs/ssr.md has the formulas. The tone map
// and encoding are shaders/include/tone_map.glsl, which render/tone_map.h compiles as C++ too. With
// set_linear_output(true) it also stores the tone map's input, exposure x (lit + reflectivity x
// reflection), into a kLinearColourFormat image (`glint render --format exr`).
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "core/math.h"
#include "render/reflection_blur_pass.h"
#include "render/reflection_denoiser.h"
#include "render/resolve_settings.h"

#include <epoxy/gl.h>

#include <optional>

namespace glint::render {

// The resolve's linear colour (with set_linear_output): float, so an EXR holds what the composite computed.
inline constexpr GLenum kLinearColourFormat = GL_RGBA32F;

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
  GLuint world_motion = 0;            // SurfaceMotion's image (deforming meshes); 0 = none moved
};

class ResolvePass {
public:
  // Compiles the shaders and creates the outputs; throws glint::Error for a non-positive size or
  // invalid settings.
  ResolvePass(int width, int height, const ResolveSettings& settings = {});

  void resize(int width, int height);
  void set_settings(const ResolveSettings& settings);  // validated; throws glint::Error
  const ResolveSettings& settings() const { return settings_; }
  // On: every later run() also stores the linear colour into linear_image() (created here; off frees it).
  void set_linear_output(bool on);

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
  // The tone map's input of the last run (kLinearColourFormat, a = 1); 0 without set_linear_output(true).
  GLuint linear_image() const { return linear_.id(); }
  int width() const { return blur_.width(); }
  int height() const { return blur_.height(); }

private:
  ReflectionBlurPass blur_;
  std::optional<ReflectionDenoiser> denoiser_;  // created by the first run with denoise
  ShaderProgram program_;
  ResolveSettings settings_;
  GlTexture final_;
  GlTexture linear_;  // with set_linear_output(true)
};

}  // namespace glint::render
