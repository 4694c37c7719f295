#include "gl/egl_context.h"
#include "gl/egl_devices.h"
#include "gl/framebuffer_readback.h"
#include "gl/gl_check.h"
#include "gl/gl_objects.h"
#include "gl_test_context.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include "support/scoped_env.h"

#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>

namespace glint {
namespace {

using GlContext = testing::GlTest;

using testing::ScopedEnv;

// Clears `framebuffer`'s first attachment to `colour` and returns its top-left pixel.
glm::u8vec4 clear_and_read(const GlFramebuffer& framebuffer, const glm::vec4& colour) {
  glClearNamedFramebufferfv(framebuffer.id(), GL_COLOR, 0, &colour.x);
  return read_framebuffer_rgba8(framebuffer, GL_COLOR_ATTACHMENT0, 4, 4).at(0, 0);
}

TEST_F(GlContext, IsOpenGl45CoreAndNamesTheRenderer) {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  EXPECT_TRUE(major > 4 || (major == 4 && minor >= 5)) << major << "." << minor;
  EXPECT_NE(profile & GL_CONTEXT_CORE_PROFILE_BIT, 0);
  EXPECT_FALSE(context().renderer().empty());
  EXPECT_FALSE(context().vendor().empty());
  EXPECT_GE(context().device_index(), 0);
  EXPECT_FALSE(context().debug_output());
  EXPECT_NE(context().description().find(context().renderer()), std::string::npos);
  std::cout << "[ context  ] " << context().description() << "\n";  // which GL the suite ran on
  check_gl("context queries");
}

TEST_F(GlContext, SecondContextOnTheSameDeviceLeavesTheFirstWorking) {
  auto texture = create_texture_2d(GL_RGBA8, 4, 4);
  auto framebuffer = create_framebuffer();
  glNamedFramebufferTexture(framebuffer.id(), GL_COLOR_ATTACHMENT0, texture.id(), 0);
  {
    HeadlessGlOptions options;
    options.device_index = context().device_index();
    options.debug_output = false;
    HeadlessGlContext second(options);
    EXPECT_EQ(second.device_index(), context().device_index());
    EXPECT_EQ(second.renderer(), context().renderer());
  }  // destroying the second context must not terminate the shared EGL display
  context().make_current();
  EXPECT_EQ(clear_and_read(framebuffer, glm::vec4(0.0f, 1.0f, 0.0f, 1.0f)), glm::u8vec4(0, 255, 0, 255));
  check_gl("after second context");
}

TEST_F(GlContext, EnvironmentDeviceIndexOutOfRangeListsTheDevices) {
  ScopedEnv env("GLINT_EGL_DEVICE", "99");
  try {
    HeadlessGlContext bad;
    FAIL() << "expected a glint::Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("GLINT_EGL_DEVICE=99"), std::string::npos) << message;
    EXPECT_NE(message.find("device 0: "), std::string::npos) << message;
    EXPECT_NE(message.find(context().device_extensions()), std::string::npos) << message;
  }
  context().make_current();
}

TEST_F(GlContext, EnvironmentDeviceIndexSelectsThatDevice) {
  ScopedEnv env("GLINT_EGL_DEVICE", std::to_string(context().device_index()).c_str());
  {
    HeadlessGlContext chosen;
    EXPECT_EQ(chosen.device_index(), context().device_index());
  }
  context().make_current();  // destroying the current context left this thread with none
}

std::vector<EglDeviceDescription> fake_devices() {
  return {{0, "EGL_MESA_device_software EGL_EXT_device_drm_render_node", ""},
          {1, "EGL_NV_device_cuda EGL_EXT_device_drm", "/dev/dri/card1"},
          {2, "EGL_EXT_device_drm", "/dev/dri/card2"},
          {3, "EGL_NV_device_cuda", ""}};
}

TEST(GlEglDevices, TriesNvidiaFirstThenTheRestByIndex) {
  EXPECT_EQ(egl_device_try_order(fake_devices()), (std::vector<int>{1, 3, 0, 2}));
  EXPECT_EQ(egl_device_try_order({}), std::vector<int>{});
}

TEST(GlEglDevices, OverrideAcceptsOnlyExistingIndices) {
  const auto devices = fake_devices();
  EXPECT_EQ(parse_egl_device_override("2", devices), 2);
  for (const char* bad : {"4", "-1", "x", "1x", " 1"}) {
    try {
      parse_egl_device_override(bad, devices);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const Error& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(std::string("GLINT_EGL_DEVICE=") + bad), std::string::npos) << message;
      EXPECT_NE(message.find("4 EGL devices"), std::string::npos) << message;
      EXPECT_NE(message.find("device 1: EGL_NV_device_cuda EGL_EXT_device_drm (/dev/dri/card1)"), std::string::npos)
          << message;
    }
  }
}

TEST(GlDebugOutputOption, ExplicitChoiceBeatsTheEnvironment) {
  ScopedEnv env("GLINT_GL_DEBUG", "1");
  HeadlessGlOptions options;
  EXPECT_TRUE(resolve_gl_debug_output(options));
  options.debug_output = false;
  EXPECT_FALSE(resolve_gl_debug_output(options));
  ScopedEnv off("GLINT_GL_DEBUG", "0");
  EXPECT_FALSE(resolve_gl_debug_output(HeadlessGlOptions{}));
}

}  // namespace
}  // namespace glint
