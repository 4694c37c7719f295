#include "gl/shader_program.h"

#include "core/error.h"
#include "gl/embedded_shaders.h"
#include "gl/shader_includes.h"

#include <fmt/format.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cctype>
#include <regex>

namespace glint {
namespace {

bool ends_with(std::string_view text, std::string_view suffix) {
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

std::string shader_info_log(GLuint shader) {
  GLint length = 0;
  glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  GLsizei written = 0;
  glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), &written, log.data());
  log.resize(static_cast<std::size_t>(written));
  return log;
}

std::string program_info_log(GLuint program) {
  GLint length = 0;
  glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
  std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
  GLsizei written = 0;
  glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), &written, log.data());
  log.resize(static_cast<std::size_t>(written));
  return log;
}

GlShader compile_stage(const ShaderStageSource& stage) {
  GlShader shader(glCreateShader(stage.stage));
  if (!shader) fail("{}: glCreateShader failed for stage {:#06x}", stage.name, stage.stage);
  const GLchar* text = stage.source.data();
  const auto length = static_cast<GLint>(stage.source.size());
  glShaderSource(shader.id(), 1, &text, &length);
  glCompileShader(shader.id());
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
  if (ok == GL_TRUE) return shader;
  const std::string log = shader_info_log(shader.id());
  // With includes, the log's line numbers belong to the file of their source-string number; a
  // legend under the log says which file each number is, for the errors after the first.
  std::string legend;
  if (stage.source_files.size() > 1) {
    legend = "\nsource-string numbers in this log:";
    for (std::size_t i = 0; i < stage.source_files.size(); ++i)
      legend.append(fmt::format("{} {} = {}", i == 0 ? "" : ",", i, stage.source_files[i]));
  }
  if (const auto where = parse_glsl_error_location(log)) {
    const auto number = static_cast<std::size_t>(where->source_string);
    const std::string& file = number < stage.source_files.size() ? stage.source_files[number] : stage.name;
    fail("{}:{}: GLSL compile error\n{}{}", file, where->line, log, legend);
  }
  fail("{}: GLSL compile error (the driver's log names no line)\n{}{}", stage.name, log, legend);
}

// Lines of `text` that contain "error" in any case, or all lines when none does.
std::vector<std::string_view> error_lines_first(std::string_view text) {
  std::vector<std::string_view> errors, all;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    all.push_back(line);
    std::string lower(line);
    for (auto& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (lower.find("error") != std::string::npos) errors.push_back(line);
    start = end + 1;
  }
  return errors.empty() ? all : errors;
}

}  // namespace

GLenum shader_stage_from_name(std::string_view name) {
  if (ends_with(name, ".vert.glsl")) return GL_VERTEX_SHADER;
  if (ends_with(name, ".frag.glsl")) return GL_FRAGMENT_SHADER;
  if (ends_with(name, ".geom.glsl")) return GL_GEOMETRY_SHADER;
  if (ends_with(name, ".comp.glsl")) return GL_COMPUTE_SHADER;
  if (ends_with(name, ".tesc.glsl")) return GL_TESS_CONTROL_SHADER;
  if (ends_with(name, ".tese.glsl")) return GL_TESS_EVALUATION_SHADER;
  fail("{}: cannot tell the shader stage; name shader files *.vert.glsl, *.frag.glsl, *.geom.glsl, "
       "*.comp.glsl, *.tesc.glsl or *.tese.glsl",
       name);
}

std::optional<GlslErrorLocation> parse_glsl_error_location(std::string_view info_log) {
  // The first number is the source-string number (0 unless #line set another), the second the line.
  static const std::regex mesa(R"((?:^|[^0-9])(\d+):(\d+)\(\d+\):)");     // 0:12(3): error: ...
  static const std::regex nvidia(R"((?:^|[^0-9])(\d+)\((\d+)\)\s*:)");    // 0(12) : error C0000: ...
  static const std::regex amd(R"((?:^|[^0-9])(\d+):(\d+):)");             // ERROR: 0:12: ...
  for (const std::string_view line : error_lines_first(info_log)) {
    std::match_results<std::string_view::const_iterator> match;
    for (const std::regex* pattern : {&mesa, &nvidia, &amd})
      if (std::regex_search(line.begin(), line.end(), match, *pattern))
        return GlslErrorLocation{std::stoi(match[1].str()), std::stoi(match[2].str())};
  }
  return std::nullopt;
}

std::optional<int> parse_glsl_error_line(std::string_view info_log) {
  if (const auto where = parse_glsl_error_location(info_log)) return where->line;
  return std::nullopt;
}

ShaderProgram ShaderProgram::from_sources(const std::vector<ShaderStageSource>& stages) {
  if (stages.empty()) fail("ShaderProgram: no shader stages given");
  std::vector<std::string> names;
  for (const auto& stage : stages) names.push_back(stage.name);
  std::string name = fmt::format("{}", fmt::join(names, " + "));

  std::vector<GlShader> shaders;
  for (const auto& stage : stages) shaders.push_back(compile_stage(stage));

  GlProgram program(glCreateProgram());
  if (!program) fail("{}: glCreateProgram failed", name);
  for (const auto& shader : shaders) glAttachShader(program.id(), shader.id());
  glLinkProgram(program.id());
  // Shaders are no longer needed once linked; detaching lets them be freed with their owners.
  for (const auto& shader : shaders) glDetachShader(program.id(), shader.id());
  GLint ok = GL_FALSE;
  glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) fail("{}: GLSL link error\n{}", name, program_info_log(program.id()));
  return ShaderProgram(std::move(program), std::move(name));
}

ShaderProgram ShaderProgram::from_embedded(std::initializer_list<std::string_view> names,
                                           std::span<const std::string_view> defines) {
  // Include names are looked up among the embedded shaders too; an unknown one is reported by the
  // expander, naming the including file and line.
  std::vector<ExpandedShaderSource> expanded;  // owns the text the stages view
  expanded.reserve(names.size());
  for (const std::string_view file : names) {
    expanded.push_back(expand_shader_includes(file, shader_source(file), find_embedded_shader, "shaders/"));
    expanded.back().text = add_shader_defines(expanded.back().text, defines);
  }
  std::vector<ShaderStageSource> stages;
  auto source = expanded.begin();
  for (const std::string_view file : names) {
    stages.push_back({shader_stage_from_name(file), fmt::format("shaders/{}", file), source->text, source->files});
    ++source;
  }
  return from_sources(stages);
}

GLint ShaderProgram::uniform_location(std::string_view uniform) {
  std::string key(uniform);
  if (const auto found = locations_.find(key); found != locations_.end()) return found->second;
  const GLint location = glGetUniformLocation(program_.id(), key.c_str());
  locations_.emplace(std::move(key), location);
  return location;
}

void ShaderProgram::set_uniform(std::string_view uniform, int value) {
  glProgramUniform1i(program_.id(), uniform_location(uniform), value);
}
void ShaderProgram::set_uniform(std::string_view uniform, float value) {
  glProgramUniform1f(program_.id(), uniform_location(uniform), value);
}
void ShaderProgram::set_uniform(std::string_view uniform, const vec2& value) {
  glProgramUniform2fv(program_.id(), uniform_location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set_uniform(std::string_view uniform, const vec3& value) {
  glProgramUniform3fv(program_.id(), uniform_location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set_uniform(std::string_view uniform, const vec4& value) {
  glProgramUniform4fv(program_.id(), uniform_location(uniform), 1, glm::value_ptr(value));
}
void ShaderProgram::set_uniform(std::string_view uniform, const mat4& value) {
  glProgramUniformMatrix4fv(program_.id(), uniform_location(uniform), 1, GL_FALSE, glm::value_ptr(value));
}

}  // namespace glint
