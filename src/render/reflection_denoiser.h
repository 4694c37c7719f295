#pragma once
// ReflectionDenoiser: the reflection filter of `--denoise on` (docs/glossy.md), run by ResolvePass
// instead of the paper's blur. Two steps, both GL compute:
//   temporal (shaders/reflection_temporal.comp.glsl): the faded reflection is blended into a history
//     reprojected by the camera's motion (the previous frame's view-projection); history taps that
//     are not the same surface (plane distance, normal) are dropped, none left = disocclusion, the
//     history restarts; the history is clamped to the 3x3 neighbourhood's mean +- k deviations;
//     mirrors (roughness 0) pass through. It also writes each pixel's guide (position, normal,
//     roughness, reflective; include/denoiser_guide.glsl), which the spatial passes read and the next
//     frame reads as the previous surface
//   spatial (shaders/reflection_spatial.comp.glsl): `iterations` a-trous passes (steps 1, 2, 4)
//     weighted by a roughness footprint, plane distance, normals and roughness
// Geometry that moves by itself (the deforming meshes) is reprojected by its own motion too: the
// pixel's previous world position is its world position plus SurfaceMotion's world motion
// (render/surface_motion.h), projected with the previous view-projection; without that image (0)
// every surface counts as static.
//   inputs:  the frame's reflection (kReflectionFormat: rgb, a = distance), G-buffer world position,
//            normal + roughness, albedo + reflectivity, FrameConstants UBO, the frame's view-projection,
//            optionally the world motion (kWorldMotionFormat)
//   outputs: output() (RGBA16F: rgb = denoised, faded reflection; a = history length, 0 non-reflective)
#include "core/math.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/resolve_settings.h"

#include <epoxy/gl.h>

#include <vector>

namespace glint::render {

struct DenoiserInputs {
  GLuint reflection = 0;              // kReflectionFormat
  GLuint world_position = 0;          // kWorldPositionFormat, w = 1 where there is geometry
  GLuint world_normal_roughness = 0;  // kWorldNormalRoughnessFormat
  GLuint albedo_reflectivity = 0;     // kAlbedoReflectivityFormat
  GLuint frame_constants = 0;         // uniform buffer (camera, reflection sampling)
  mat4 view_projection{1.0f};         // this frame's, kept as the next frame's previous one
  GLuint world_motion = 0;            // kWorldMotionFormat (SurfaceMotion); 0: nothing moved by itself
};

class ReflectionDenoiser {
public:
  // Throws glint::Error for a non-positive size.
  ReflectionDenoiser(int width, int height);

  // Filters one frame (fade, temporal, spatial by `settings`); the first frame after construction
  // or reset() has no history. Inputs are checked. Ends with an image/texture barrier.
  void run(const DenoiserInputs& inputs, const ResolveSettings& settings);
  void reset() { has_history_ = false; }

  GLuint output() const { return filtered_[last_output_].id(); }
  // The last temporal result (rgb, a = history length) at reflective pixels; others undefined.
  GLuint accumulated() const { return history_[current_ ^ 1].id(); }
  // On: later runs also record every pixel's motion for read_motion() (tests; off by default, it
  // costs a write of 8 bytes a pixel).
  void record_motion(bool on);
  // The last run's motion per pixel (camera and surface; rows bottom first): where the pixel's
  // surface was on the previous frame's screen, in pixels (centres at +0.5), or (-1, -1) where the
  // history restarted (no history, disocclusion, a mirror, a non-reflective pixel). Needs
  // record_motion(true) before that run (glint::Error otherwise). Waits for the GPU (tests).
  std::vector<vec2> read_motion() const;
  int width() const { return width_; }
  int height() const { return height_; }

private:
  ShaderProgram temporal_;
  ShaderProgram spatial_;
  int width_, height_;
  GlTexture history_[2];  // RGBA16F ping-pong: rgb, a = history length
  GlTexture filtered_[2];
  GlTexture guide_[2];  // RG32UI ping-pong: this frame's guide, the previous frame's
  GlBuffer motion_;     // with record_motion(true)
  int current_ = 0;
  int last_output_ = 0;
  mat4 previous_view_projection_{1.0f};
  bool has_history_ = false;
  bool motion_recorded_ = false;  // the last run recorded motion_
};

}  // namespace glint::render
