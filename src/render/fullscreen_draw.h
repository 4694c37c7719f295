#pragma once
// What every full-screen fragment pass shares: a framebuffer with one colour target, a program made
// of shaders/fullscreen.vert.glsl and the pass's fragment shader, and the draw of one triangle that
// covers the viewport (no vertex attributes; core GL still needs a vertex array bound).
#include "gl/gl_objects.h"
#include "gl/shader_program.h"

#include <string_view>

namespace glint::render {

class FullscreenDraw {
public:
  // `target` is the colour texture written; `target_name` names it in framebuffer errors.
  FullscreenDraw(GLuint target, std::string_view target_name, std::string_view fragment_shader);

  ShaderProgram& program() { return program_; }

  // Draws into the target over (0, 0)-(width, height) with depth test and blending off, then
  // restores the default bindings. Textures and uniforms are the caller's.
  void draw(int width, int height);

private:
  GlFramebuffer framebuffer_;
  GlVertexArray empty_vertex_array_;
  ShaderProgram program_;
};

}  // namespace glint::render
