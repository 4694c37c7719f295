#pragma once
// Base fixture for GL tests: one HeadlessGlContext per test suite (creating one costs tens of
// milliseconds on llvmpipe), and every test of the suite skips with the reason when this machine
// has no EGL device with OpenGL 4.5 core.
#include "core/error.h"
#include "gl/egl_context.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace glint::testing {

template <bool DebugOutput = false>
class GlTestBase : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    try {
      HeadlessGlOptions options;
      options.debug_output = DebugOutput;
      context_ = std::make_unique<HeadlessGlContext>(options);
    } catch (const Error& error) {
      skip_reason_ = error.what();
    }
  }
  static void TearDownTestSuite() { context_.reset(); }

  void SetUp() override {
    if (!context_) GTEST_SKIP() << "no headless OpenGL 4.5: " << skip_reason_;
  }

  static HeadlessGlContext& context() { return *context_; }

private:
  static inline std::unique_ptr<HeadlessGlContext> context_;
  static inline std::string skip_reason_;
};

// Release-style context (errors through glGetError) and one with KHR_debug output on.
using GlTest = GlTestBase<false>;
using GlDebugTest = GlTestBase<true>;

}  // namespace glint::testing
