#include "gl/embedded_shaders.h"

#include "core/error.h"

#include <fmt/format.h>

namespace glint {

std::optional<std::string_view> find_embedded_shader(std::string_view name) {
  for (std::size_t i = 0; i < kEmbeddedShaderCount; ++i)
    if (kEmbeddedShaders[i].name == name) return kEmbeddedShaders[i].source;
  return std::nullopt;
}

std::string_view shader_source(std::string_view name) {
  if (const auto source = find_embedded_shader(name)) return *source;
  fail("unknown shader '{}': not among the shaders embedded from shaders/ ({}); "
       "a new shaders/*.glsl file needs a rebuild to be embedded",
       name, fmt::join(embedded_shader_names(), ", "));
}

std::vector<std::string_view> embedded_shader_names() {
  std::vector<std::string_view> names;
  names.reserve(kEmbeddedShaderCount);
  for (std::size_t i = 0; i < kEmbeddedShaderCount; ++i) names.push_back(kEmbeddedShaders[i].name);
  return names;  // already sorted: the generator sorts the file list
}

}  // namespace glint
