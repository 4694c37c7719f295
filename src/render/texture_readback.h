#pragma once
// Reads a whole 2D texture back to the CPU, top row first (GL's row 0 is the bottom; rows are
// flipped like framebuffer_readback.h does). For debug views and tests: it waits for the GPU.
#include "core/image.h"

#include <epoxy/gl.h>

namespace glint::render {

// `internal_format` says how to read it: RGBA formats come back as they are (normalised formats as
// 0..1); one-channel formats (R8, R32UI ids, depth) come back as (v, v, v, 1), ids converted to
// float exactly (below 2^24). Other formats are a glint::Error.
ImageRgbaF read_texture_rgbaf(GLuint texture, GLenum internal_format, int width, int height);

}  // namespace glint::render
