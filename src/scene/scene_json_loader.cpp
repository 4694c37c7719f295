#include "scene/scene_json_loader.h"

#include "core/error.h"
#include "scene/scene_json_builder.h"
#include "scene/scene_json_parser.h"

#include <fstream>
#include <sstream>

namespace glint {

Scene load_scene_json(const std::filesystem::path& path, const LoadOptions& options) {
  std::ifstream file(path, std::ios::binary);
  if (!file) fail("{}: cannot open the scene file", path.string());
  std::ostringstream text;
  text << file.rdbuf();
  return load_scene_json_text(text.str(), path, options);
}

Scene load_scene_json_text(std::string_view text, const std::filesystem::path& origin, const LoadOptions& options) {
  // Parse and check everything first; only then read mesh files.
  return build_scene(parse_scene_description(text, origin), options);
}

}  // namespace glint
