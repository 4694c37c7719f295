#pragma once
// One entry point for "a scene the user named": a preset name, or a file whose extension picks the
// loader (.obj, .gltf, .glb, .scene.json). Errors name the file and position.
#include "scene/load_options.h"
#include "scene/scene.h"

#include <string_view>

namespace glint {

Scene load_scene(std::string_view preset_or_path, const LoadOptions& options = {});

}  // namespace glint
