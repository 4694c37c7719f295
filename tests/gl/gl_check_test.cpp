#include "core/log.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"
#include "gl_test_context.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

using GlCheck = testing::GlTest;
using GlDebugOutput = testing::GlDebugTest;

constexpr GLenum kNotACapability = 0x1234;  // glEnable(this) is GL_INVALID_ENUM everywhere

std::string check_error(const char* what) {
  try {
    check_gl(what);
  } catch (const Error& error) {
    return error.what();
  }
  return "(no error)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(GlPassScope, NestsAndRestoresTheOuterName) {
  EXPECT_EQ(current_gl_pass(), "(no pass)");
  {
    GlPassScope outer("shadow");
    EXPECT_EQ(current_gl_pass(), "shadow");
    {
      GlPassScope inner("shadow/face 3");
      EXPECT_EQ(current_gl_pass(), "shadow/face 3");
    }
    EXPECT_EQ(current_gl_pass(), "shadow");
  }
  EXPECT_EQ(current_gl_pass(), "(no pass)");
}

TEST_F(GlCheck, NoErrorPasses) {
  glEnable(GL_DEPTH_TEST);
  EXPECT_NO_THROW(check_gl("enable depth test"));
}

TEST_F(GlCheck, ErrorNamesWhatTheCodeAndThePass) {
  GlPassScope pass("ssr");
  glEnable(kNotACapability);
  const std::string message = check_error("after ssr");
  EXPECT_TRUE(contains(message, "after ssr: GL_INVALID_ENUM in pass 'ssr'")) << message;
  EXPECT_NO_THROW(check_gl("next check")) << "one fault must be reported once";
}

TEST_F(GlDebugOutput, IsSynchronousAndOn) {
  EXPECT_TRUE(context().debug_output());
  EXPECT_EQ(glIsEnabled(GL_DEBUG_OUTPUT), GL_TRUE);
  EXPECT_EQ(glIsEnabled(GL_DEBUG_OUTPUT_SYNCHRONOUS), GL_TRUE);
}

TEST_F(GlDebugOutput, ErrorIsBlamedOnThePassThatCausedItNotTheOneThatChecks) {
  {
    GlPassScope pass("shadow cube");
    glEnable(kNotACapability);
  }
  GlPassScope later("composite");
  const std::string message = check_error("end of frame");
  EXPECT_TRUE(contains(message, "end of frame: GL error in pass 'shadow cube'")) << message;
  EXPECT_TRUE(contains(message, "[GL_INVALID_ENUM]")) << message;
  EXPECT_NO_THROW(check_gl("next check")) << "one fault must be reported once";
}

TEST_F(GlDebugOutput, LaterErrorsAreCountedBehindTheFirst) {
  glEnable(kNotACapability);
  glDisable(kNotACapability);
  const std::string message = check_error("two faults");
  EXPECT_TRUE(contains(message, "(and 1 more GL errors)")) << message;
}

TEST_F(GlDebugOutput, ApplicationErrorMessageBecomesAGlintError) {
  GlPassScope pass("trace");
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_ERROR, 7, GL_DEBUG_SEVERITY_HIGH, -1,
                       "hit buffer overflow");
  const std::string message = check_error("after trace");
  EXPECT_TRUE(contains(message, "after trace: GL error in pass 'trace': hit buffer overflow")) << message;
}

TEST_F(GlDebugOutput, OtherMessagesGoToTheLogBySeverity) {
  ScopedLogCapture capture;
  GlPassScope pass("blur");
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, 1, GL_DEBUG_SEVERITY_NOTIFICATION, -1,
                       "marker note");
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_OTHER, 2, GL_DEBUG_SEVERITY_LOW, -1, "low note");
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PERFORMANCE, 3, GL_DEBUG_SEVERITY_HIGH, -1,
                       "slow path");
  int debug_notes = 0;
  for (const auto& entry : capture.entries())
    if (entry.level == LogLevel::debug && (contains(entry.message, "marker note") || contains(entry.message, "low note")))
      ++debug_notes;
  EXPECT_EQ(debug_notes, 2);
  EXPECT_EQ(capture.count_warnings("GL performance in pass 'blur': slow path"), 1);
  EXPECT_NO_THROW(check_gl("log only"));
}

}  // namespace
}  // namespace glint
