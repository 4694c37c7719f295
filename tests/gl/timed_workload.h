#pragma once
// What the GPU-timing tests time (gpu_timer_test, scope_profiler_test): a full-screen triangle into a
// 256x256 target, and both ways glint times passes.
#include "gl/gl_objects.h"
#include "gl/gpu_timer.h"
#include "gl/shader_program.h"

namespace glint::testing {

inline constexpr PassTimingMethod kTimingMethods[] = {PassTimingMethod::gpu_queries, PassTimingMethod::finish_wall_clock};

class FullScreenWorkload {
public:
  FullScreenWorkload()
      : colour_(create_texture_2d(GL_RGBA8, 256, 256)),
        framebuffer_(create_framebuffer()),
        vertex_array_(create_vertex_array()),
        program_(ShaderProgram::from_embedded({"fullscreen.vert.glsl", "solid_color.frag.glsl"})) {
    glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, colour_.id(), 0);
    program_.set_uniform("color", vec4(0.5f));
  }
  void draw() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
    glViewport(0, 0, 256, 256);
    program_.use();
    glBindVertexArray(vertex_array_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

private:
  GlTexture colour_;
  GlFramebuffer framebuffer_;
  GlVertexArray vertex_array_;
  ShaderProgram program_;
};

}  // namespace glint::testing
