// PLACEHOLDER until the scene JSON loader lands (replaced by its implementation).
#include "scene/scene_json_loader.h"
#include "core/error.h"
namespace glint {
Scene load_scene_json(const std::filesystem::path& path, const LoadOptions&) { fail("{}: scene files are not supported yet", path.string()); }
Scene load_scene_json_text(std::string_view, const std::filesystem::path& origin, const LoadOptions&) { fail("{}: scene files are not supported yet", origin.string()); }
}  // namespace glint
