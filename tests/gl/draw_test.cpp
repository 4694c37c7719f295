// End-to-end: programs, buffers, vertex arrays, framebuffers and readback together produce exact pixels.
#include "gl/embedded_shaders.h"
#include "gl/framebuffer_readback.h"
#include "gl/gl_check.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "gl_test_context.h"

#include <gtest/gtest.h>

#include <array>

namespace glint {
namespace {

using GlDraw = testing::GlTest;

struct Target {
  GlTexture colour;
  GlFramebuffer framebuffer;
  int width, height;
};

Target make_target(GLenum format, int width, int height) {
  Target target{create_texture_2d(format, width, height), create_framebuffer(), width, height};
  glNamedFramebufferTexture(target.framebuffer.id(), GL_COLOR_ATTACHMENT0, target.colour.id(), 0);
  require_framebuffer_complete(target.framebuffer, "test target");
  const glm::vec4 clear(0.0f);
  glClearNamedFramebufferfv(target.framebuffer.id(), GL_COLOR, 0, &clear.x);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer.id());
  glViewport(0, 0, width, height);
  return target;
}

void draw_fullscreen(ShaderProgram& program, const GlVertexArray& vertex_array) {
  program.use();
  glBindVertexArray(vertex_array.id());  // core profile needs one bound even without attributes
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

TEST_F(GlDraw, FullscreenTriangleGivesEveryPixelTheExactColour) {
  const Target target = make_target(GL_RGBA8, 61, 37);  // odd sizes catch off-by-one coverage
  ShaderProgram program = ShaderProgram::from_embedded({"fullscreen.vert.glsl", "solid_color.frag.glsl"});
  program.set_uniform("color", vec4(51.0f, 102.0f, 153.0f, 204.0f) / 255.0f);
  const GlVertexArray vertex_array = create_vertex_array();
  draw_fullscreen(program, vertex_array);
  check_gl("fullscreen draw");

  const ImageRgba8 image = read_framebuffer_rgba8(target.framebuffer, GL_COLOR_ATTACHMENT0, 61, 37);
  ASSERT_EQ(image.width, 61);
  ASSERT_EQ(image.height, 37);
  int wrong = 0;
  for (const auto& pixel : image.pixels) wrong += pixel != glm::u8vec4(51, 102, 153, 204);
  EXPECT_EQ(wrong, 0);
}

TEST_F(GlDraw, FloatTargetReadsBackExactValuesOutsideZeroToOne) {
  const Target target = make_target(GL_RGBA32F, 8, 4);
  ShaderProgram program = ShaderProgram::from_embedded({"fullscreen.vert.glsl", "solid_color.frag.glsl"});
  program.set_uniform("color", vec4(0.25f, -2.0f, 1000.5f, 0.125f));  // G-buffer positions are like this
  draw_fullscreen(program, create_vertex_array());
  const ImageRgbaF image = read_framebuffer_rgbaf(target.framebuffer, GL_COLOR_ATTACHMENT0, 8, 4);
  for (const auto& pixel : image.pixels) ASSERT_EQ(pixel, vec4(0.25f, -2.0f, 1000.5f, 0.125f));
}

// A triangle over the top-left corner: covered pixels must come back in the top-left of the image
// (rows flipped to top-first), and pixels beyond its diagonal must stay clear.
TEST_F(GlDraw, SmallTriangleCoversItsInsideOnlyAndReadsBackTopRowFirst) {
  constexpr int size = 64;
  const Target target = make_target(GL_RGBA8, size, size);
  const std::string vertex_source =
      "#version 450 core\n"
      "layout(location = 0) in vec2 position;\n"
      "void main() { gl_Position = vec4(position, 0.0, 1.0); }\n";
  ShaderProgram program = ShaderProgram::from_sources(
      {{GL_VERTEX_SHADER, "small_triangle_test.vert.glsl", vertex_source},
       {GL_FRAGMENT_SHADER, "shaders/solid_color.frag.glsl", shader_source("solid_color.frag.glsl")}});
  program.set_uniform("color", vec4(1.0f, 0.0f, 1.0f, 1.0f));

  // Clip space: (-1, 1) is the top-left corner; the triangle's legs are half the screen long.
  const std::array<vec2, 3> corners = {vec2(-1.0f, 1.0f), vec2(0.0f, 1.0f), vec2(-1.0f, 0.0f)};
  const GlBuffer vertices = create_buffer(std::span<const vec2>(corners));
  const GlVertexArray vertex_array = create_vertex_array();
  glVertexArrayVertexBuffer(vertex_array.id(), 0, vertices.id(), 0, sizeof(vec2));
  glEnableVertexArrayAttrib(vertex_array.id(), 0);
  glVertexArrayAttribFormat(vertex_array.id(), 0, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vertex_array.id(), 0, 0);
  program.use();
  glBindVertexArray(vertex_array.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  check_gl("small triangle draw");

  const ImageRgba8 image = read_framebuffer_rgba8(target.framebuffer, GL_COLOR_ATTACHMENT0, size, size);
  // In top-first pixel coordinates the triangle is x + y < 32 (pixel centres at +0.5); pixels whose
  // centre lies exactly on the diagonal (x + y == 31) follow the rasterizer's tie rule, so skip them.
  const glm::u8vec4 inside(255, 0, 255, 255), outside(0, 0, 0, 0);
  int wrong = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      if (x + y == 31) continue;
      const glm::u8vec4 expected = x + y < 31 ? inside : outside;
      if (image.at(x, y) != expected) {
        if (++wrong <= 5) ADD_FAILURE() << "pixel (" << x << ", " << y << ") is wrong";
      }
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_EQ(image.at(0, 0), inside);
  EXPECT_EQ(image.at(0, size - 1), outside);  // bottom-left: would be covered if rows were not flipped
}

}  // namespace
}  // namespace glint
