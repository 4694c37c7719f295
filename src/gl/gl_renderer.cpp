#include "gl/gl_renderer.h"

#include <epoxy/gl.h>

namespace glint {

std::string current_gl_renderer() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return renderer != nullptr ? renderer : "";
}

bool software_gl_renderer(std::string_view gl_renderer) {
  return gl_renderer.find("llvmpipe") != std::string_view::npos ||
         gl_renderer.find("softpipe") != std::string_view::npos;
}

}  // namespace glint
