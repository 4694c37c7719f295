#pragma once
// glint's scene description (*.scene.json, format in docs/scene-format.md): meshes from OBJ/glTF
// files placed with transforms and material overrides, deformers, the light and its path, the camera
// path, frame count and floor reflectivity. Unknown keys are errors that name their JSON path.
#include "scene/load_options.h"
#include "scene/scene.h"

#include <filesystem>
#include <string_view>

namespace glint {

Scene load_scene_json(const std::filesystem::path& path, const LoadOptions& options = {});

// The same from text already in memory; `origin` names it in errors and is the base for relative
// paths (as if the text had been read from that file).
Scene load_scene_json_text(std::string_view text, const std::filesystem::path& origin, const LoadOptions& options = {});

}  // namespace glint
