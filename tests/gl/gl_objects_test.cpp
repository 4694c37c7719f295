#include "gl/gl_check.h"
#include "gl/gl_objects.h"
#include "gl_test_context.h"

#include <gtest/gtest.h>

#include <array>
#include <string>

namespace glint {
namespace {

using GlObjects = testing::GlTest;

TEST_F(GlObjects, MoveTransfersOwnershipAndResetDeletes) {
  const std::array<float, 4> data = {1.0f, 2.0f, 3.0f, 4.0f};
  GlBuffer first = create_buffer(std::span<const float>(data));
  const GLuint id = first.id();
  ASSERT_NE(id, 0u);
  GlBuffer second = std::move(first);
  EXPECT_EQ(first.id(), 0u);  // NOLINT(bugprone-use-after-move): checking the moved-from state
  EXPECT_EQ(second.id(), id);
  EXPECT_EQ(glIsBuffer(id), GL_TRUE);

  std::array<float, 4> back{};
  glGetNamedBufferSubData(second.id(), 0, sizeof(back), back.data());
  EXPECT_EQ(back, data);

  second = GlBuffer();  // move-assigning deletes the old buffer
  EXPECT_EQ(glIsBuffer(id), GL_FALSE);
  check_gl("buffer lifetime");
}

TEST_F(GlObjects, TexturesHaveImmutableStorageOfTheAskedSize) {
  const GlTexture texture = create_texture_2d(GL_RGBA16F, 40, 30, 3);
  const GlTexture cube = create_texture_cube(GL_DEPTH_COMPONENT32F, 64);
  GLint immutable = 0, width = 0, height = 0, levels = 0;
  glGetTextureParameteriv(texture.id(), GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
  glGetTextureParameteriv(texture.id(), GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  glGetTextureLevelParameteriv(texture.id(), 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(texture.id(), 0, GL_TEXTURE_HEIGHT, &height);
  EXPECT_EQ(immutable, GL_TRUE);
  EXPECT_EQ(levels, 3);
  EXPECT_EQ(width, 40);
  EXPECT_EQ(height, 30);
  GLint target = 0;
  glGetTextureParameteriv(cube.id(), GL_TEXTURE_TARGET, &target);
  EXPECT_EQ(target, GL_TEXTURE_CUBE_MAP);
  check_gl("texture storage");
  EXPECT_THROW(create_texture_2d(GL_RGBA8, 0, 4), Error);
}

TEST_F(GlObjects, IncompleteFramebufferIsAnErrorNamingTheStatus) {
  const GlFramebuffer empty = create_framebuffer();
  try {
    require_framebuffer_complete(empty, "gbuffer");
    FAIL() << "expected a glint::Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("gbuffer: framebuffer is not complete (GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT"),
              std::string::npos)
        << message;
  }
  const GlTexture colour = create_texture_2d(GL_RGBA8, 4, 4);
  glNamedFramebufferTexture(empty.id(), GL_COLOR_ATTACHMENT0, colour.id(), 0);
  EXPECT_NO_THROW(require_framebuffer_complete(empty, "gbuffer"));
  check_gl("framebuffer completeness");
}

}  // namespace
}  // namespace glint
