#pragma once
// A linked GLSL program. Every failure is a glint::Error that names the shader file and, for compile
// errors, the line the driver reported, with the driver's full log underneath
// ("shaders/ssr.frag.glsl:42: GLSL compile error\n0:42(7): error: ..."). Embedded shaders may use
// `#include "include/x.glsl"` (see shader_includes.h); an error inside an included file names that
// file and its own line ("shaders/include/x.glsl:12: GLSL compile error").
#include "core/math.h"
#include "gl/gl_objects.h"

#include <epoxy/gl.h>

#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace glint {

struct ShaderStageSource {
  GLenum stage;             // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...
  std::string name;         // shown in errors: the file name, e.g. "shaders/ssr.frag.glsl"
  std::string_view source;  // complete GLSL source, starting with #version
  // Display name of each GLSL source-string number that `#line <line> <number>` directives in
  // `source` use (ExpandedShaderSource::files); empty when every line belongs to `name`.
  std::vector<std::string> source_files = {};
};

// The stage a file name declares by its suffix: .vert.glsl, .frag.glsl, .geom.glsl, .comp.glsl,
// .tesc.glsl, .tese.glsl. Any other name is a glint::Error.
GLenum shader_stage_from_name(std::string_view name);

// Where the first error of a compiler info log is: the GLSL source-string number (set by #line
// directives; 0 without them) and the line, from Mesa's "0:12(3): error", NVIDIA's "0(12) : error"
// or AMD's "ERROR: 0:12:" format; nullopt when the log names no line.
struct GlslErrorLocation {
  int source_string = 0;
  int line = 0;
};
std::optional<GlslErrorLocation> parse_glsl_error_location(std::string_view info_log);
// Only the line of parse_glsl_error_location.
std::optional<int> parse_glsl_error_line(std::string_view info_log);

class ShaderProgram {
public:
  // Compiles every stage and links them into one program.
  static ShaderProgram from_sources(const std::vector<ShaderStageSource>& stages);
  // The same from shaders embedded from shaders/ (see embedded_shaders.h), stage from the suffix,
  // after expanding their #include lines from the embedded shaders (shader_includes.h):
  // ShaderProgram::from_embedded({"fullscreen.vert.glsl", "solid_color.frag.glsl"}).
  // `defines` become `#define NAME 1` at the top of every stage (add_shader_defines).
  static ShaderProgram from_embedded(std::initializer_list<std::string_view> names,
                                     std::span<const std::string_view> defines = {});

  GLuint id() const { return program_.id(); }
  const std::string& name() const { return name_; }  // "a.vert.glsl + b.frag.glsl"
  void use() const { glUseProgram(program_.id()); }

  // Location of a uniform, or -1 when the program has no such active uniform (the compiler removes
  // unused ones, so -1 is not an error; setting -1 is a no-op in GL).
  GLint uniform_location(std::string_view uniform);

  // Direct-state-access setters (glProgramUniform*): no need to bind the program first.
  void set_uniform(std::string_view uniform, int value);
  void set_uniform(std::string_view uniform, float value);
  void set_uniform(std::string_view uniform, const vec2& value);
  void set_uniform(std::string_view uniform, const vec3& value);
  void set_uniform(std::string_view uniform, const vec4& value);
  void set_uniform(std::string_view uniform, const mat4& value);

private:
  ShaderProgram(GlProgram program, std::string name) : program_(std::move(program)), name_(std::move(name)) {}

  GlProgram program_;
  std::string name_;
  std::unordered_map<std::string, GLint> locations_;  // glGetUniformLocation is a string lookup
};

}  // namespace glint
