#include "scene/texture_io.h"

#include "core/error.h"
#include "core/log.h"
#include "core/untrusted_text.h"
#include "scene/stb_image_guard.h"

#include <stb/stb_image.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>
#include <system_error>
#include <vector>

namespace glint {
namespace {

Texture checker_standing_in_for(const std::filesystem::path& path) {
  Texture texture = make_checker_texture();
  texture.name = path.string();  // says which file is missing; placeholder = true says it is a checker
  return texture;
}

bool starts_with(std::span<const unsigned char> bytes, std::string_view magic) {
  return bytes.size() >= magic.size() && std::equal(magic.begin(), magic.end(), bytes.begin(),
                                                    [](char m, unsigned char b) { return static_cast<unsigned char>(m) == b; });
}

// The format the first bytes announce, for messages ("image" when they announce none: TGA has no
// signature).
std::string_view format_name(std::span<const unsigned char> bytes) {
  if (starts_with(bytes, "\x89PNG")) return "PNG";
  if (starts_with(bytes, "\xFF\xD8")) return "JPEG";
  if (starts_with(bytes, "BM")) return "BMP";
  if (starts_with(bytes, "GIF8")) return "GIF";
  if (starts_with(bytes, "8BPS")) return "PSD";
  if (starts_with(bytes, "#?RADIANCE") || starts_with(bytes, "#?RGBE")) return "HDR";
  return "image";
}

std::vector<unsigned char> read_file_bytes(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) fail("cannot open the file");
  std::vector<unsigned char> bytes;
  file.seekg(0, std::ios::end);
  const std::streamoff size = file.tellg();
  file.seekg(0);
  if (size < 0) fail("cannot read the file");
  bytes.resize(static_cast<std::size_t>(size));
  if (!file.read(reinterpret_cast<char*>(bytes.data()), size)) fail("cannot read the file");
  return bytes;
}

}  // namespace

Texture decode_texture(std::span<const unsigned char> encoded, const std::string& name) {
  if (encoded.empty()) fail("the file is empty");
  // stb takes the size as an int; a larger buffer cannot hold an image glint accepts anyway.
  if (encoded.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    fail("{} bytes is more than any texture within glint's limit", encoded.size());
  const std::string_view format = format_name(encoded);
  const int size = static_cast<int>(encoded.size());
  check_before_stb_image(encoded);  // inputs that stb_image 2.27 mishandles (stb_image_guard.h)
  int width = 0, height = 0, channels_in_file = 0;
  if (stbi_info_from_memory(encoded.data(), size, &width, &height, &channels_in_file) == 0) {
    // stb_image's own reason is left out: it is the last format it tried that set it, so a damaged
    // JPEG reads "bad png sig".
    if (format == "image") fail("not an image glint can read (PNG, JPEG, TGA, BMP, GIF, PSD, HDR, PIC or PNM)");
    fail("the {} header is damaged or uses a variant glint cannot read", format);
  }
  const std::uint64_t texels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  if (width <= 0 || height <= 0 || texels > kMaxTextureTexels)
    fail("the {} header declares {} x {} texels, more than glint's limit of {} texels (16384 x 16384)", format,
         width, height, kMaxTextureTexels);
  // stb's flip flag is process-wide state; pin it for this thread so that rows always come top row
  // first, the convention of scene.h, whatever another caller set.
  stbi_set_flip_vertically_on_load_thread(0);
  int decoded_width = 0, decoded_height = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(encoded.data(), size, &decoded_width, &decoded_height, &channels_in_file, 4),
      &stbi_image_free);
  if (!pixels) fail("the {} data is damaged or uses a variant glint cannot read", format);
  if (decoded_width != width || decoded_height != height)  // the header was read twice: never expected to differ
    fail("the {} decoded as {} x {} texels, but its header says {} x {}", format, decoded_width, decoded_height, width, height);
  Texture texture;
  texture.name = name;
  texture.width = width;
  texture.height = height;
  texture.rgba.assign(pixels.get(), pixels.get() + texels * 4);
  return texture;
}

Texture load_texture_or_placeholder(const std::filesystem::path& path, std::string_view referenced_by) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    log_warning("{}: texture '{}' not found; using a checker placeholder", referenced_by, untrusted_text(path.string()));
    return checker_standing_in_for(path);
  }
  try {
    return decode_texture(read_file_bytes(path), path.string());
  } catch (const Error& e) {
    log_warning("{}: texture '{}' cannot be read: {}; using a checker placeholder", referenced_by,
                untrusted_text(path.string()), e.what());
    return checker_standing_in_for(path);
  }
}

Texture make_checker_texture(int size, int square) {
  if (size <= 0 || square <= 0) fail("checker texture: size ({}) and square ({}) must be positive", size, square);
  Texture texture;
  texture.name = "procedural:checker";
  texture.width = size;
  texture.height = size;
  texture.placeholder = true;
  texture.rgba.resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      // Magenta on black: a colour no real material has, so a missing texture is obvious on screen.
      const bool magenta = ((x / square) + (y / square)) % 2 == 0;
      std::uint8_t* texel = &texture.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(size) + static_cast<std::size_t>(x)) * 4];
      texel[0] = magenta ? 255 : 0;
      texel[1] = 0;
      texel[2] = magenta ? 255 : 0;
      texel[3] = 255;
    }
  return texture;
}

}  // namespace glint
