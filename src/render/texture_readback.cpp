#include "render/texture_readback.h"

#include "core/error.h"
#include "gl/gl_check.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace glint::render {
namespace {

template <typename T>
std::vector<T> read_texels(GLuint texture, GLenum format, GLenum type, std::size_t count) {
  std::vector<T> texels(count);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture, 0, format, type, static_cast<GLsizei>(texels.size() * sizeof(T)), texels.data());
  check_gl("texture readback");
  return texels;
}

}  // namespace

ImageRgbaF read_texture_rgbaf(GLuint texture, GLenum internal_format, int width, int height) {
  if (width <= 0 || height <= 0) fail("texture readback: invalid size {}x{}", width, height);
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  ImageRgbaF image(width, height);
  const auto store = [&](std::size_t i, glm::vec4 value) {
    // Row i / width counted from the bottom goes to row height - 1 - that from the top.
    const int x = static_cast<int>(i % static_cast<std::size_t>(width));
    const int y = static_cast<int>(i / static_cast<std::size_t>(width));
    image.at(x, height - 1 - y) = value;
  };
  switch (internal_format) {
    case GL_RGBA8:
    case GL_RGBA16F:
    case GL_RGBA32F: {
      const auto texels = read_texels<glm::vec4>(texture, GL_RGBA, GL_FLOAT, pixels);
      for (std::size_t i = 0; i < pixels; ++i) store(i, texels[i]);
      break;
    }
    case GL_R8:
    case GL_R16F:
    case GL_R32F: {
      const auto texels = read_texels<float>(texture, GL_RED, GL_FLOAT, pixels);
      for (std::size_t i = 0; i < pixels; ++i) store(i, glm::vec4(glm::vec3(texels[i]), 1.0f));
      break;
    }
    case GL_R8UI:
    case GL_R32UI: {
      const auto texels = read_texels<std::uint32_t>(texture, GL_RED_INTEGER, GL_UNSIGNED_INT, pixels);
      for (std::size_t i = 0; i < pixels; ++i) store(i, glm::vec4(glm::vec3(static_cast<float>(texels[i])), 1.0f));
      break;
    }
    case GL_DEPTH_COMPONENT32F:
    case GL_DEPTH_COMPONENT24: {
      const auto texels = read_texels<float>(texture, GL_DEPTH_COMPONENT, GL_FLOAT, pixels);
      for (std::size_t i = 0; i < pixels; ++i) store(i, glm::vec4(glm::vec3(texels[i]), 1.0f));
      break;
    }
    default:
      fail("texture readback: internal format {:#06x} is not supported", internal_format);
  }
  return image;
}

}  // namespace glint::render
