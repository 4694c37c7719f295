// PLACEHOLDER until the built-in scenes land (replaced by their implementation).
#include "scene/presets.h"
#include "core/error.h"
namespace glint {
std::vector<std::string> preset_names() { return {"atrium", "atrium-simple", "sponza"}; }
bool is_preset_name(std::string_view name) { return name == "atrium" || name == "atrium-simple" || name == "sponza"; }
Scene make_preset(std::string_view name, const LoadOptions&) { fail("{}: built-in scenes are not built yet", name); }
}  // namespace glint
