#pragma once
// The shaders/*.glsl files, embedded into the binary at build time (cmake/GlintShaders.cmake), so
// glint runs from any folder without the source tree. Shaders are looked up by file name relative to
// shaders/, e.g. shader_source("fullscreen.vert.glsl").
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace glint {

struct EmbeddedShader {
  std::string_view name;    // path relative to shaders/, e.g. "fullscreen.vert.glsl"
  std::string_view source;  // the file's exact contents
};

// Defined in the generated glint_embedded_shaders.cpp.
extern const EmbeddedShader kEmbeddedShaders[];
extern const std::size_t kEmbeddedShaderCount;

// The source of an embedded shader; an unknown name is a glint::Error listing the known ones.
std::string_view shader_source(std::string_view name);

// The source of an embedded shader, or nullopt for an unknown name (the lookup that #include
// expansion uses for embedded shaders: see shader_includes.h).
std::optional<std::string_view> find_embedded_shader(std::string_view name);

// Names of all embedded shaders, sorted.
std::vector<std::string_view> embedded_shader_names();

}  // namespace glint
