#pragma once
// The built-in scenes, needing no files: `atrium`, `atrium-simple` (procedural, see
// scene/procedural/atrium.h) and `sponza` (the example scene file over ../shared/assets).
#include "scene/load_options.h"
#include "scene/scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace glint {

std::vector<std::string> preset_names();
bool is_preset_name(std::string_view name);
Scene make_preset(std::string_view name, const LoadOptions& options = {});

}  // namespace glint
