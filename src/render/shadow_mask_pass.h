#pragma once
// ShadowMaskPass: per G-buffer pixel, is the point light visible? A compute pass, one invocation per
// pixel, PCF over the cube map.
//   inputs:  RasterTargets world_position and world_normal_roughness, ShadowCubePass's cube map,
//            FrameConstants UBO at kFrameConstantsBinding (light position)
//   outputs: RasterTargets shadow_mask (kShadowMaskFormat: 1 lit, 0 shadowed, fractional at PCF
//            edges, 1 for background)
// Bias and normal offset are in cube texels at the receiver (see shaders/shadow_mask.comp.glsl).
#include "gl/shader_program.h"
#include "render/raster_settings.h"
#include "render/raster_targets.h"
#include "render/shadow_cube_pass.h"

namespace glint::render {

class ShadowMaskPass {
public:
  explicit ShadowMaskPass(const RasterTargets& targets);  // the targets must outlive the pass

  void run(const ShadowCubePass& cube, const RasterSettings& settings);

private:
  const RasterTargets* targets_;
  ShaderProgram program_;
};

}  // namespace glint::render
