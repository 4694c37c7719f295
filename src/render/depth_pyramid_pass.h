#pragma once
// DepthPyramidPass: the hierarchical depth (hi-Z) pyramid SSR traces over, built each frame by
// compute shaders from the G-buffer. Level 0 holds, per pixel, the range [min, max] of positive
// linear view depths its surface covers (the plane of its world position and normal across the
// pixel's footprint, shaders/depth_pyramid_base.comp.glsl); each further level the min of the
// minima and max of the maxima of the texels under it (shaders/depth_pyramid_reduce.comp.glsl),
// down to 1 texel. Background is infinitely far (kPyramidBackgroundDepth). docs/ssr.md "Depth
// pyramid".
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
  // Builds every level (one dispatch per level, barriers between). Inputs are checked like the
  // other passes' (ids, sizes, formats). Ends with a barrier for texture fetches and image loads.
  void run(const DepthPyramidInputs& inputs);

  GLuint texture() const { return pyramid_.id(); }
  int levels() const { return levels_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // Levels of a full mip chain of a width x height image: floor(log2(max(width, height))) + 1.
  static int level_count(int width, int height);

private:
  ShaderProgram base_;
  ShaderProgram reduce_;
  GlTexture pyramid_;
  int width_ = 0;
  int height_ = 0;
  int levels_ = 0;
};

}  // namespace glint::render
