#include "gl/embedded_shaders.h"

#include "core/error.h"
#include "core/log.h"

#include <fmt/format.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <string>

namespace glint {
namespace {

// GLINT_SHADER_DIR: shader development without a rebuild. A file of that folder with a shader's name
// replaces the embedded copy (read once per process and kept, so every program of the run compiles
// the same text); names the folder lacks stay embedded. A run that uses it says so once, since its
// images and timings are then those of other shaders than the binary's.
std::optional<std::string_view> find_override_shader(std::string_view name) {
  const char* const folder = std::getenv("GLINT_SHADER_DIR");
  if (folder == nullptr || *folder == '\0') return std::nullopt;
  static std::mutex mutex;
  static std::map<std::string, std::optional<std::string>, std::less<>> read;  // path -> text, or absent
  const std::lock_guard lock(mutex);
  const std::string path = (std::filesystem::path(folder) / std::string(name)).string();
  auto it = read.find(path);
  if (it == read.end()) {
    std::optional<std::string> text;
    if (std::ifstream file{path, std::ios::binary}) {
      std::ostringstream contents;
      contents << file.rdbuf();
      if (file.bad()) fail("{}: cannot read this shader (GLINT_SHADER_DIR)", path);
      text = contents.str();
      log_warning("{} replaces the embedded shader '{}' (GLINT_SHADER_DIR)", path, name);
    }
    it = read.emplace(path, std::move(text)).first;
  }
  if (!it->second) return std::nullopt;
  return std::string_view(*it->second);
}

}  // namespace

std::optional<std::string_view> find_embedded_shader(std::string_view name) {
  if (const auto replaced = find_override_shader(name)) return replaced;
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
