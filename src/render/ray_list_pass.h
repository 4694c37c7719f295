#pragma once
// RayListPass: the first step of the ray-traced complement. One compute dispatch over the G-buffer
// lists a mirror ray for every pixel that needs a ray-traced reflection (shaders/ray_list.comp.glsl
// states the rule and the ray), into RayHitBuffers' rays and pixels, counting them.
//   inputs:  G-buffer albedo_reflectivity, world_position, world_normal_roughness; SSR's failure
//            mask (hybrid) or none (rt: every reflective pixel); FrameConstants UBO (camera)
//   outputs: RayHitBuffers rays [0, count), pixels [0, count), counters
#include "gl/shader_program.h"
#include "render/ray_hit_buffers.h"
#include "render/tile_dispatch.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <optional>

namespace glint::render {

// --reflections auto: the ray list runs over the tiles of a list (render/tile_dispatch.h) and lists
// at most max_rays rays (the frame's budget; the rest of the pixels that wanted one keep what SSR
// gave them).
struct RayListTiles {
  TileListDispatch tiles;
  std::uint32_t max_rays = 0;
};

struct RayListInputs {
  GLuint albedo_reflectivity = 0;  // kAlbedoReflectivityFormat
  GLuint world_position = 0;       // kWorldPositionFormat
  GLuint world_normal = 0;         // kWorldNormalRoughnessFormat
  GLuint failure_mask = 0;         // kFailureMaskFormat; 0 = list every reflective pixel (rt mode)
  GLuint frame_constants = 0;      // uniform buffer holding FrameConstants
};

class RayListPass {
public:
  // Compiles the shader; throws glint::Error for a non-positive size or a buffer capacity below
  // width x height (every pixel may need a ray).
  RayListPass(int width, int height, RayHitBuffers& buffers);

  // World distance a ray's origin is moved along the surface normal, so the ray does not hit the
  // surface it starts on. Must be >= 0 and finite.
  void set_origin_offset(float offset);

  // Zeroes the counters and dispatches the pass; inputs are checked like every pass's (glint::Error
  // naming the input). Call buffers.finish_ray_list() to read the count and the rays.
  void run(const RayListInputs& inputs);

  // From the next run() on: only the listed tiles, within a budget (nullopt: the whole image, no budget).
  void set_tiles(const std::optional<RayListTiles>& tiles) { tiles_ = tiles; }

private:
  std::uint32_t capacity_limit() const;  // the buffers' capacity, as a GLSL int

  ShaderProgram program_;
  ShaderProgram clamp_program_;  // ray_budget_clamp.comp.glsl
  std::optional<RayListTiles> tiles_;
  RayHitBuffers* buffers_;
  int width_, height_;
  GlTexture no_failure_mask_;  // bound in rt mode: the shader ignores it there
};

}  // namespace glint::render
