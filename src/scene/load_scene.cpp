#include "scene/load_scene.h"

#include "core/error.h"
#include "scene/coordinate_precision.h"
#include "scene/gltf_loader.h"
#include "scene/obj_loader.h"
#include "scene/presets.h"
#include "scene/scene_json_loader.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace glint {
namespace {

bool ends_with_ignoring_case(std::string_view text, std::string_view suffix) {
  if (text.size() < suffix.size()) return false;
  return std::equal(suffix.begin(), suffix.end(), text.end() - static_cast<std::ptrdiff_t>(suffix.size()),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b)); });
}

}  // namespace

Scene load_scene(std::string_view preset_or_path, const LoadOptions& options) {
  if (is_preset_name(preset_or_path)) return make_preset(preset_or_path, options);

  const std::filesystem::path path{std::string(preset_or_path)};
  const std::string name = path.filename().string();
  const bool known_extension = ends_with_ignoring_case(name, ".obj") || ends_with_ignoring_case(name, ".gltf") ||
                               ends_with_ignoring_case(name, ".glb") || ends_with_ignoring_case(name, ".scene.json");
  if (!known_extension) {
    std::string presets;
    for (const std::string& preset : preset_names()) presets += (presets.empty() ? "" : ", ") + preset;
    fail("{}: not a preset ({}) nor a scene file (.obj, .gltf, .glb, .scene.json)", preset_or_path, presets);
  }
  if (!std::filesystem::exists(path)) fail("{}: no such file", path.string());
  if (std::filesystem::is_directory(path)) fail("{}: is a directory, not a scene file", path.string());

  Scene scene = ends_with_ignoring_case(name, ".obj")          ? load_obj(path, options)
                : ends_with_ignoring_case(name, ".scene.json") ? load_scene_json(path, options)
                                                               : load_gltf(path, options);
  warn_about_coarse_coordinates(scene);
  return scene;
}

}  // namespace glint
