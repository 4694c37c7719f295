#include "gl/embedded_shaders.h"
#include "gl/gl_check.h"
#include "gl/shader_includes.h"
#include "gl/shader_program.h"
#include "gl_test_context.h"

#include <gtest/gtest.h>

#include "support/error_of.h"

#include "support/scoped_env.h"
#include "support/temp_folder.h"
#include "support/test_paths.h"

#include <fstream>
#include <map>
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

TEST(GlEmbeddedShaders, ShaderDirReplacesOnlyTheFilesItHolds) {
  testing::TempFolder folder;
  {
    std::ofstream file(folder.path() / "solid_color.frag.glsl", std::ios::binary);
    file << "// replaced\n";
  }
  const std::string embedded(shader_source("solid_color.frag.glsl"));
  {
    const testing::ScopedEnv env("GLINT_SHADER_DIR", folder.path().string());
    EXPECT_EQ(shader_source("solid_color.frag.glsl"), "// replaced\n");
    // A name the folder lacks stays embedded; an unknown one is still an error.
    EXPECT_EQ(*find_embedded_shader("fullscreen.vert.glsl"), shader_source("fullscreen.vert.glsl"));
    EXPECT_NE(shader_source("fullscreen.vert.glsl").find("#version"), std::string_view::npos);
    EXPECT_FALSE(find_embedded_shader("no_such_pass.frag.glsl"));
  }
  EXPECT_EQ(shader_source("solid_color.frag.glsl"), embedded);
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

TEST(GlShaderLog, FindsTheSourceStringNumber) {
  const auto mesa = parse_glsl_error_location("2:12(3): error: syntax error\n");
  ASSERT_TRUE(mesa);
  EXPECT_EQ(mesa->source_string, 2);
  EXPECT_EQ(mesa->line, 12);
  const auto nvidia = parse_glsl_error_location("3(7) : error C0000: syntax error\n");
  ASSERT_TRUE(nvidia);
  EXPECT_EQ(nvidia->source_string, 3);
  EXPECT_EQ(nvidia->line, 7);
  const auto amd = parse_glsl_error_location("ERROR: 1:42: 'x' : undeclared identifier\n");
  ASSERT_TRUE(amd);
  EXPECT_EQ(amd->source_string, 1);
  EXPECT_EQ(amd->line, 42);
}

TEST_F(GlShaderProgram, EveryEmbeddedPassWithIncludesCompilesAndLinks) {
  // The pass shaders that include shaders/include/*.glsl, in the stage combinations the passes use.
  ShaderProgram lighting = ShaderProgram::from_embedded({"lighting.comp.glsl"});
  EXPECT_GE(lighting.uniform_location("ambient_fraction"), 0);
  ShaderProgram mask = ShaderProgram::from_embedded({"shadow_mask.comp.glsl"});
  for (const char* uniform : {"near_distance", "texel_angle", "pcf_radius_texels", "constant_bias_texels",
                              "slope_bias_texels", "normal_offset_texels"})
    EXPECT_GE(mask.uniform_location(uniform), 0) << uniform;
  ShaderProgram gbuffer = ShaderProgram::from_embedded({"gbuffer.vert.glsl", "gbuffer.frag.glsl"});
  EXPECT_NE(gbuffer.id(), 0u);
  ShaderProgram cube =
      ShaderProgram::from_embedded({"shadow_cube.vert.glsl", "shadow_cube.geom.glsl", "shadow_cube.frag.glsl"});
  EXPECT_GE(cube.uniform_location("face_view_projection[5]"), 0);
  ShaderProgram ssr = ShaderProgram::from_embedded({"ssr.comp.glsl"});
  EXPECT_GE(ssr.uniform_location("max_steps"), 0);
  check_gl("programs with includes");
}

// A compute shader like the coming hit-shading pass: every scene buffer, the surface lighting and
// the cube-map shadow at arbitrary points, with its own sampler binding; all must compile together.
TEST_F(GlShaderProgram, SharedIncludesCompileTogetherInAComputeShader) {
  const std::string source =
      "#version 450 core\n"
      "layout(local_size_x = 64) in;\n"
      "#include \"include/scene_buffers.glsl\"\n"
      "#include \"include/frame_constants.glsl\"\n"
      "#include \"include/surface_lighting.glsl\"\n"
      "#include \"include/cube_shadow.glsl\"\n"
      "layout(binding = 3) uniform samplerCube hit_shadow_cube;\n"
      "layout(std430, binding = 6) writeonly buffer Out { vec4 radiance[]; };\n"
      "void main() {\n"
      "  uint i = gl_GlobalInvocationID.x;\n"
      "  GpuInstance instance = instances[i];\n"
      "  GpuMeshRange range = mesh_ranges[instance.mesh];\n"
      "  GpuVertex v = vertices[range.base_vertex + indices[range.first_index]];\n"
      "  vec3 p = (instance.model * vec4(v.position_u.xyz, 1.0)).xyz;\n"
      "  vec3 n = normalize(mat3(instance.normal_matrix) * v.normal_v.xyz);\n"
      "  CubeShadowSettings s = CubeShadowSettings(light_position_range.xyz, 10.0, 0.01, 1.0, 1.0, 1.0, 1.0);\n"
      "  float shadow = cube_shadow_visibility(hit_shadow_cube, s, p, n);\n"
      "  GpuMaterial m = materials[instance.material];\n"
      "  radiance[i] = vec4(surface_radiance(p, n, normalize(camera_position.xyz - p), m.diffuse.rgb, m,\n"
      "                                      shadow, 0.1), 1.0);\n"
      "}\n";
  const ExpandedShaderSource expanded =
      expand_shader_includes("hit_test.comp.glsl", source, find_embedded_shader, "shaders/");
  ShaderProgram program =
      ShaderProgram::from_sources({{GL_COMPUTE_SHADER, "shaders/hit_test.comp.glsl", expanded.text, expanded.files}});
  EXPECT_NE(program.id(), 0u);
  check_gl("compute shader with every shared include");
}

ShaderStageSource fullscreen_vertex() {
  return {GL_VERTEX_SHADER, "shaders/fullscreen.vert.glsl", shader_source("fullscreen.vert.glsl")};
}

TEST_F(GlShaderProgram, ErrorInAnIncludedFileNamesThatFileAndLine) {
  const std::map<std::string, std::string, std::less<>> files = {
      {"include/fine.glsl", "// fine\nfloat fine() { return 1.0; }\n"},
      {"include/broken.glsl",
       "// 1\n"
       "#include \"include/fine.glsl\"\n"  // 2
       "float broken() {\n"                 // 3
       "  return fine() * ;\n"              // 4: the error
       "}\n"},
  };
  const ShaderIncludeLookup lookup = [&](std::string_view name) -> std::optional<std::string_view> {
    const auto found = files.find(name);
    if (found == files.end()) return std::nullopt;
    return std::string_view(found->second);
  };
  const std::string top =
      "#version 450 core\n"
      "#include \"include/fine.glsl\"\n"
      "#include \"include/broken.glsl\"\n"
      "layout(location = 0) out vec4 c;\n"
      "void main() { c = vec4(broken()); }\n";
  const ExpandedShaderSource expanded = expand_shader_includes("uses_broken.frag.glsl", top, lookup, "shaders/");
  const std::string message = error_of([&] {
    ShaderProgram::from_sources({fullscreen_vertex(),
                                 {GL_FRAGMENT_SHADER, "shaders/uses_broken.frag.glsl", expanded.text, expanded.files}});
  });
  EXPECT_EQ(message.rfind("shaders/include/broken.glsl:4: GLSL compile error\n", 0), 0u) << message;
  EXPECT_NE(message.find("2 = shaders/include/broken.glsl"), std::string::npos) << message;

  // An error after the include, in the top file, keeps the top file's own line numbers.
  const std::string top_error =
      "#version 450 core\n"
      "#include \"include/fine.glsl\"\n"
      "layout(location = 0) out vec4 c;\n"
      "void main() { c = vec4(fine()) * ; }\n";  // line 4
  const ExpandedShaderSource expanded_top =
      expand_shader_includes("top_error.frag.glsl", top_error, lookup, "shaders/");
  const std::string top_message = error_of([&] {
    ShaderProgram::from_sources(
        {fullscreen_vertex(), {GL_FRAGMENT_SHADER, "shaders/top_error.frag.glsl", expanded_top.text, expanded_top.files}});
  });
  EXPECT_EQ(top_message.rfind("shaders/top_error.frag.glsl:4: GLSL compile error\n", 0), 0u) << top_message;
}

TEST(GlEmbeddedShaders, EveryPassShaderExpandsItsIncludes) {
  // Every embedded pass shader expands: no include names a file that is not embedded.
  for (const std::string_view name : embedded_shader_names()) {
    if (name.substr(0, 8) == "include/") continue;
    EXPECT_NO_THROW(expand_shader_includes(name, shader_source(name), find_embedded_shader, "shaders/")) << name;
  }
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
