#include "gl/framebuffer_readback.h"

#include "core/error.h"
#include "gl/gl_check.h"

#include <algorithm>

namespace glint {
namespace {

template <typename Pixel>
Image<Pixel> read_attachment(const GlFramebuffer& framebuffer, GLenum attachment, int width, int height,
                             GLenum type) {
  if (width <= 0 || height <= 0) fail("framebuffer readback: invalid size {}x{}", width, height);
  Image<Pixel> image(width, height);
  // glReadnPixels reads from the bound read framebuffer; restore the caller's binding afterwards.
  GLint previous = 0;
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &previous);
  glNamedFramebufferReadBuffer(framebuffer.id(), attachment);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer.id());
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadnPixels(0, 0, width, height, GL_RGBA, type, static_cast<GLsizei>(image.pixels.size() * sizeof(Pixel)),
                image.pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(previous));
  check_gl("framebuffer readback");
  // GL's row 0 is the bottom row; ours is the top.
  for (int y = 0; y < height / 2; ++y)
    std::swap_ranges(&image.at(0, y), &image.at(0, y) + width, &image.at(0, height - 1 - y));
  return image;
}

}  // namespace

ImageRgba8 read_framebuffer_rgba8(const GlFramebuffer& framebuffer, GLenum attachment, int width, int height) {
  return read_attachment<glm::u8vec4>(framebuffer, attachment, width, height, GL_UNSIGNED_BYTE);
}

ImageRgbaF read_framebuffer_rgbaf(const GlFramebuffer& framebuffer, GLenum attachment, int width, int height) {
  return read_attachment<glm::vec4>(framebuffer, attachment, width, height, GL_FLOAT);
}

}  // namespace glint
