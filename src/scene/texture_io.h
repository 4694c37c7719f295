#pragma once
// Texture files (PNG, JPG, TGA, BMP via stb_image) and the checker that stands in for a missing one.
#include "scene/scene.h"

#include <filesystem>
#include <string_view>

namespace glint {

// Loads an image as 8-bit RGBA. A missing or unreadable file is not fatal: a warning naming the
// file and `referenced_by` (e.g. "sponza.mtl:12") is logged and a checker placeholder returned.
Texture load_texture_or_placeholder(const std::filesystem::path& path, std::string_view referenced_by);

// A magenta/black checker, size x size texels, squares of `square` texels; placeholder = true.
Texture make_checker_texture(int size = 64, int square = 8);

}  // namespace glint
