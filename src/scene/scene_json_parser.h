#pragma once
// Step 1 of loading a scene file: JSON text -> SceneDescription, checking every key, type and value.
// Reads no other file. Errors are one glint::Error "<origin>: <JSON pointer>: <problem>", or
// "<origin>:<line>:<column>: malformed JSON: ..." for syntax errors.
#include "scene/scene_description.h"

#include <filesystem>
#include <string_view>

namespace glint {

SceneDescription parse_scene_description(std::string_view text, const std::filesystem::path& origin);

}  // namespace glint
