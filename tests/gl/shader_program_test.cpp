#include "gl/embedded_shaders.h"
#include "gl/gl_check.h"
#include "gl/shader_program.h"
#include "gl_test_context.h"

#include <gtest/gtest.h>

#include "support/error_of.h"

#include "support/test_paths.h"

#include <fstream>
#include <sstream>
#include <string>

namespace glint {
namespace {

using GlShaderProgram = testing::GlTest;

using testing::error_of;

TEST(GlShaderLog, FindsTheLineInMesaNvidiaAndAmdLogs) {
  EXPECT_EQ(parse_glsl_error_line("0:12(3): error: syntax error, unexpected '}'\n"), 12);
  EXPECT_EQ(parse_glsl_error_line("0(7) : error C0000: syntax error, unexpected '}' at token \"}\"\n"), 7);
  EXPECT_EQ(parse_glsl_error_line("ERROR: 0:42: 'x' : undeclared identifier\n"), 42);
  // The first error wins, even after a warning on another line.
  EXPECT_EQ(parse_glsl_error_line("0:3(1): warning: unused variable\n0:9(14): error: `y' undeclared\n"
                                  "0:11(2): error: another\n"),
            9);
  EXPECT_EQ(parse_glsl_error_line("0(30) : warning C7050: \"v\" might be used uninitialized\n"
                                  "0(31) : error C1008: undefined variable \"w\"\n"),
            31);
}

TEST(GlShaderLog, NoLineNumberGivesNothing) {
  EXPECT_EQ(parse_glsl_error_line(""), std::nullopt);
  EXPECT_EQ(parse_glsl_error_line("error: linking failed\n"), std::nullopt);
}

TEST(GlShaderStage, ComesFromTheFileSuffix) {
  EXPECT_EQ(shader_stage_from_name("fullscreen.vert.glsl"), static_cast<GLenum>(GL_VERTEX_SHADER));
  EXPECT_EQ(shader_stage_from_name("a/b.frag.glsl"), static_cast<GLenum>(GL_FRAGMENT_SHADER));
  EXPECT_EQ(shader_stage_from_name("shade_hits.comp.glsl"), static_cast<GLenum>(GL_COMPUTE_SHADER));
  EXPECT_NE(error_of([] { shader_stage_from_name("ssr.glsl"); }).find("ssr.glsl"), std::string::npos);
}

TEST(GlEmbeddedShaders, EmbedsTheFilesExactly) {
  for (const char* name : {"fullscreen.vert.glsl", "solid_color.frag.glsl"}) {
    std::ifstream file((testing::source_dir() / "shaders" / name).string(), std::ios::binary);
    ASSERT_TRUE(file) << name;
    std::stringstream contents;
    contents << file.rdbuf();
    EXPECT_EQ(shader_source(name), contents.str()) << name;
  }
  const auto names = embedded_shader_names();
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
}

TEST(GlEmbeddedShaders, UnknownNameIsAnErrorListingTheKnownOnes) {
  const std::string message = error_of([] { shader_source("no_such_pass.frag.glsl"); });
  EXPECT_NE(message.find("no_such_pass.frag.glsl"), std::string::npos) << message;
  EXPECT_NE(message.find("fullscreen.vert.glsl"), std::string::npos) << message;
}

TEST_F(GlShaderProgram, SyntaxErrorNamesTheFileAndTheDriversLine) {
  const std::string source =
      "#version 450 core\n"                 // 1
      "layout(location = 0) out vec4 c;\n"  // 2
      "void main() {\n"                     // 3
      "  c = vec4(1.0);\n"                  // 4
      "  c = vec4(1.0) * ;\n"               // 5: the error
      "}\n";
  const std::string message = error_of([&] {
    ShaderProgram::from_sources({{GL_VERTEX_SHADER, "shaders/fullscreen.vert.glsl", shader_source("fullscreen.vert.glsl")},
                                 {GL_FRAGMENT_SHADER, "broken_test.frag.glsl", source}});
  });
  EXPECT_NE(message.find("broken_test.frag.glsl:5: GLSL compile error"), std::string::npos) << message;
  EXPECT_NE(message.find('\n'), std::string::npos) << "the driver's log should follow: " << message;
  check_gl("after a failed compile");  // a failed compile is not a GL error
}

TEST_F(GlShaderProgram, LinkErrorNamesTheProgram) {
  const std::string source =
      "#version 450 core\n"
      "layout(location = 0) out vec4 c;\n"
      "vec4 declared_but_never_defined();\n"
      "void main() { c = declared_but_never_defined(); }\n";
  const std::string message = error_of([&] {
    ShaderProgram::from_sources({{GL_VERTEX_SHADER, "shaders/fullscreen.vert.glsl", shader_source("fullscreen.vert.glsl")},
                                 {GL_FRAGMENT_SHADER, "unlinked_test.frag.glsl", source}});
  });
  EXPECT_NE(message.find("shaders/fullscreen.vert.glsl + unlinked_test.frag.glsl: GLSL link error"), std::string::npos)
      << message;
}

TEST_F(GlShaderProgram, EmbeddedProgramLinksAndFindsItsUniform) {
  ShaderProgram program = ShaderProgram::from_embedded({"fullscreen.vert.glsl", "solid_color.frag.glsl"});
  EXPECT_NE(program.id(), 0u);
  EXPECT_EQ(program.name(), "shaders/fullscreen.vert.glsl + shaders/solid_color.frag.glsl");
  EXPECT_GE(program.uniform_location("color"), 0);
  EXPECT_EQ(program.uniform_location("not_a_uniform"), -1);
  program.set_uniform("color", vec4(1.0f));
  program.set_uniform("not_a_uniform", 1.0f);  // location -1: ignored by GL, not an error
  check_gl("uniforms");
}

TEST_F(GlShaderProgram, MovedFromProgramOwnsNothing) {
  ShaderProgram first = ShaderProgram::from_embedded({"fullscreen.vert.glsl", "solid_color.frag.glsl"});
  const GLuint id = first.id();
  ShaderProgram second = std::move(first);
  EXPECT_EQ(second.id(), id);
  EXPECT_EQ(first.id(), 0u);  // NOLINT(bugprone-use-after-move): checking the moved-from state
  EXPECT_EQ(glIsProgram(id), GL_TRUE);
}

}  // namespace
}  // namespace glint
