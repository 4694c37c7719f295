#pragma once
// DepthPyramidPass: the hierarchical depth (hi-Z) pyramid SSR traces over, built each frame by
// compute shaders from the G-buffer. Level 0 holds, per pixel, the range [min, max] of positive
// linear view depths its surface covers (the plane of its world position and normal across the
// pixel's footprint); each further level the min of the minima and max of the maxima of the texels
// under it, the last texel of a row or column also taking the finer level's last where that is odd
// (both rules in shaders/include/depth_pyramid.glsl), down to 1 texel. Background is infinitely far
// (kPyramidBackgroundDepth). docs/ssr.md "Depth pyramid".
//
// Two dispatches, not one per level: a dispatch and barrier per level cost more than the work of
// the small levels. (1) depth_pyramid_tiles.comp.glsl: one work group per texel of level 5 (fewer
// on small images) computes level 0 for every pixel under it and reduces levels 1..5 in shared
// memory; (2) depth_pyramid_tail.comp.glsl: one work group builds the remaining levels from the
// image, with a work-group barrier between levels (images of 8192 pixels or more a side, over 13
// levels, take a further tail dispatch: see depth_pyramid_tail.comp.glsl).
#include "gl/gl_objects.h"
#include "gl/shader_program.h"

#include <epoxy/gl.h>

namespace glint::render {

inline constexpr GLenum kDepthPyramidFormat = GL_RG32F;  // r = min depth, g = max depth
inline constexpr float kPyramidBackgroundDepth = 3.0e38f;

struct DepthPyramidInputs {
  GLuint world_position = 0;   // kWorldPositionFormat; w = 0 background
  GLuint world_normal = 0;     // kWorldNormalRoughnessFormat
  GLuint frame_constants = 0;  // uniform buffer holding FrameConstants
};

class DepthPyramidPass {
public:
  DepthPyramidPass(int width, int height);  // throws glint::Error for a non-positive size

  void resize(int width, int height);
  // Builds every level in two dispatches (tiles, then tail: see the top of this file). Inputs are
  // checked like the other passes' (ids, sizes, formats). Ends with a barrier for texture fetches
  // and image loads.
  void run(const DepthPyramidInputs& inputs);

  GLuint texture() const { return pyramid_.id(); }
  int levels() const { return levels_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // Levels of a full mip chain of a width x height image: floor(log2(max(width, height))) + 1.
  static int level_count(int width, int height);

private:
  ShaderProgram tiles_;
  ShaderProgram tail_;
  GlTexture pyramid_;
  int width_ = 0;
  int height_ = 0;
  int levels_ = 0;
};

}  // namespace glint::render
