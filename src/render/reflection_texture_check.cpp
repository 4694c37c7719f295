#include "render/reflection_texture_check.h"

#include "core/error.h"

namespace glint::render {

void require_texture(const char* pass, const char* input, GLuint texture, GLenum internal_format, int width,
                     int height) {
  if (texture == 0) fail("{}: input '{}' is texture 0 (not set)", pass, input);
  if (glIsTexture(texture) != GL_TRUE) fail("{}: input '{}' ({}) is not a texture", pass, input, texture);
  GLint w = 0, h = 0, format = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &w);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_HEIGHT, &h);
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  if (w != width || h != height) fail("{}: input '{}' is {}x{}, the pass is {}x{}", pass, input, w, h, width, height);
  if (static_cast<GLenum>(format) != internal_format)
    fail("{}: input '{}' has internal format {:#06x}, expected {:#06x} (see render_targets.h)", pass, input,
         static_cast<unsigned>(format), internal_format);
}

void require_buffer(const char* pass, const char* input, GLuint buffer) {
  if (buffer == 0) fail("{}: input '{}' is buffer 0 (not set)", pass, input);
  if (glIsBuffer(buffer) != GL_TRUE) fail("{}: input '{}' ({}) is not a buffer", pass, input, buffer);
}

void require_pass_size(const char* pass, int width, int height) {
  if (width <= 0 || height <= 0) fail("{}: invalid size {}x{}", pass, width, height);
}

}  // namespace glint::render
