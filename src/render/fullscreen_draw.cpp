#include "render/fullscreen_draw.h"

#include <string>

namespace glint::render {

FullscreenDraw::FullscreenDraw(GLuint target, std::string_view target_name, std::string_view fragment_shader)
    : framebuffer_(create_framebuffer()),
      empty_vertex_array_(create_vertex_array()),
      program_(ShaderProgram::from_embedded({"fullscreen.vert.glsl", fragment_shader})) {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, target, 0);
  require_framebuffer_complete(framebuffer_, std::string(target_name).c_str());
}

void FullscreenDraw::draw(int width, int height) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, width, height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  program_.use();
  glBindVertexArray(empty_vertex_array_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
}

}  // namespace glint::render
