#pragma once
// SsrPass: screen-space reflections for every reflective pixel of the G-buffer, in two halves:
//   march (G-buffer only): the depth pyramid (DepthPyramidPass: per-pixel depth ranges, min/max mip
//     chain), then one compute dispatch traces each pixel's mirror ray through it hierarchically (a
//     perspective-correct screen-space line, cell by cell, a level up over empty cells and down
//     where the ray meets the depth range), judges the hit, and writes the failure mask, the
//     counters and the trusted hits (hits(), shaders/include/ssr_hit.glsl);
//   shade (needs the lit image): the colour where each trusted hit's ray met the surface.
// When a device backend traces shadow and reflection rays, FramePipeline marches before lighting, so
// that the ray list and every trace of the frame share one GL-CUDA hand-over, and shades after it;
// otherwise run() does both in one dispatch after lighting (cheaper: no hits written and read back).
// Together they write
//   reflection (kReflectionFormat): rgb = lit colour at the trusted hit, a = world distance from the
//                                   surface to the hit; 0 where the pixel is not reflective or failed;
//   failure mask (kFailureMaskFormat): 1 where a reflective pixel needs a ray-traced reflection;
//   pixel counters: a 2-uint SSBO at binding kPixelCountersBinding, [0] reflective pixels and
//                   [1] failed pixels (an SSBO with atomicAdd, one add per work group and counter,
//                   not an atomic-counter buffer).
// docs/ssr.md states the algorithm, the thickness model, the failure rules and the confidence formula.
#include "gl/gl_objects.h"
#include "gl/readback_ring.h"
#include "gl/shader_program.h"
#include "render/depth_pyramid_pass.h"
#include "render/ssr_settings.h"
#include "render/tile_dispatch.h"

#include <epoxy/gl.h>

#include <cstddef>
#include <cstdint>
#include <optional>

namespace glint::render {

// Inputs, all width x height in the formats of render_targets.h. The depth buffer is not needed:
// the pyramid takes each pixel's linear depth from the world position (exact, where a 32-bit
// perspective depth loses precision far away), its background flag from position.w and the slope
// of its surface from the normal.
struct SsrInputs {
  GLuint albedo_reflectivity = 0;  // kAlbedoReflectivityFormat; a = reflectivity
  GLuint world_position = 0;       // kWorldPositionFormat; w = 1 geometry, 0 background
  GLuint world_normal = 0;         // kWorldNormalRoughnessFormat
  GLuint lit = 0;                  // kLitFormat; the colour a hit reflects
  GLuint frame_constants = 0;      // uniform buffer holding FrameConstants (frame_constants.h)
};

struct SsrCounts {
  std::uint32_t reflective = 0;  // pixels with geometry and reflectivity > 0
  std::uint32_t failed = 0;      // reflective pixels left for the ray tracer (failure mask = 1)
};

class SsrPass {
public:
  // Compiles shaders/ssr.comp.glsl and creates the outputs; throws glint::Error for a non-positive
  // size or invalid settings.
  SsrPass(int width, int height, const SsrSettings& settings = {});

  // Recreates the outputs for a new size (their contents are undefined until the next run()).
  void resize(int width, int height);
  void set_settings(const SsrSettings& settings);  // validated; throws glint::Error
  // --reflections auto: run() marches only the tiles of this list (one work group per listed tile,
  // an indirect dispatch; render/tile_dispatch.h); pixels of other tiles are left as they were.
  void set_tile_list(const std::optional<TileListDispatch>& tiles) { tiles_ = tiles; }
  const SsrSettings& settings() const { return settings_; }

  // Clears the counters, builds the pyramid and marches, fetching each trusted hit's colour as it
  // goes: march() and shade() in one dispatch, for a frame with no hand-over to share (docs/ssr.md
  // "March, then colour"). Inputs are checked (ids, sizes, formats) and a mismatch is a
  // glint::Error. Each of the three ends with a memory barrier that makes its outputs visible to any
  // later image load, texture fetch, readback or buffer read.
  void run(const SsrInputs& inputs);
  // The march alone: the failure mask, the counters, the hits, and the reflection image's distances
  // (its rgb 0). inputs.lit is not read, so it can run before lighting.
  void march(const SsrInputs& inputs);
  // The colour at the last march's trusted hits from inputs.lit, into the reflection's rgb
  // (glint::Error before any march()).
  void shade(const SsrInputs& inputs);

  GLuint reflection() const { return reflection_.id(); }
  GLuint failure_mask() const { return failure_mask_.id(); }
  GLuint hits() const { return hits_.id(); }  // kSsrHitFormat; 0 until the first march()
  GLuint counters_buffer() const { return counters_.id(); }
  const DepthPyramidPass& depth_pyramid() const { return pyramid_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // The counters of the last run(). It waits for the GPU: for tests, statistics and debug output,
  // never inside timed frame code.
  SsrCounts read_counts() const;
  // Without waiting: queues a copy of the last run()'s counters into readback slot `slot`
  // (< kFramesInFlight), and reads it frames later, once the GPU is past it (or waiting when
  // `wait`; nullopt when it is not there yet and `wait` is false).
  void request_counts(std::size_t slot);
  std::optional<SsrCounts> requested_counts(std::size_t slot, bool wait);

private:
  void dispatch_march(const SsrInputs& inputs, bool colour_in_march);

  ShaderProgram program_;         // ssr.comp.glsl: the march with the colour fetch (run)
  ShaderProgram march_program_;   // ssr_march.comp.glsl: the march alone (march)
  ShaderProgram colour_program_;  // ssr_colour.comp.glsl: the colour fetch
  DepthPyramidPass pyramid_;
  SsrSettings settings_;
  int width_ = 0;
  int height_ = 0;
  GlTexture reflection_;
  GlTexture failure_mask_;
  GlTexture hits_;
  GlBuffer counters_;
  ReadbackRing counts_readback_;
  std::optional<TileListDispatch> tiles_;
};

}  // namespace glint::render
