#pragma once
// Texture files (PNG, JPG, TGA, BMP via stb_image) and the checker that stands in for a missing one.
#include "scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

namespace glint {

// The one size limit of every texture glint decodes (texture files, glTF images, any format): a
// header that declares more texels than this is refused before any pixel is allocated. 2^28 texels
// (16384 x 16384) is 1 GiB of RGBA8, the decoded size stb_image's PNG reader already refused to
// exceed; its JPEG, TGA, BMP, ... readers had no such bound (a 248-byte JPEG could claim 20000 x
// 20000). Textures are resampled to layers of at most 1024 x 1024 anyway (render/texture_layers.h).
inline constexpr std::uint64_t kMaxTextureTexels = std::uint64_t{1} << 28;

// An encoded image (PNG, JPEG, TGA, BMP, GIF, PSD, HDR, PIC, PNM) decoded as 8-bit RGBA, top row
// first, named `name`. Its dimensions are read from the header first and checked against
// kMaxTextureTexels. Throws a glint::Error whose message is only the reason, in words ("a JPEG
// header declares 20000 x 20000 texels, more than glint's limit of ..."): callers prefix the file.
Texture decode_texture(std::span<const unsigned char> encoded, const std::string& name);

// Loads an image as 8-bit RGBA. A missing or unreadable file is not fatal: a warning naming the
// file, `referenced_by` (e.g. "sponza.mtl:12") and the reason is logged and a checker placeholder
// returned.
Texture load_texture_or_placeholder(const std::filesystem::path& path, std::string_view referenced_by);

// A magenta/black checker, size x size texels, squares of `square` texels; placeholder = true.
Texture make_checker_texture(int size = 64, int square = 8);

}  // namespace glint
