#pragma once
// Reads a framebuffer's colour attachment back to the CPU as an image, top row first (GL stores
// rows bottom-first, so the rows are flipped). For tests, reference images and output frames; it
// waits for the GPU, so never call it inside a timed frame.
#include "core/image.h"
#include "gl/gl_objects.h"

namespace glint {

// `attachment` is GL_COLOR_ATTACHMENT0 + i; the region is (0, 0)-(width, height).
ImageRgba8 read_framebuffer_rgba8(const GlFramebuffer& framebuffer, GLenum attachment, int width, int height);
ImageRgbaF read_framebuffer_rgbaf(const GlFramebuffer& framebuffer, GLenum attachment, int width, int height);

}  // namespace glint
