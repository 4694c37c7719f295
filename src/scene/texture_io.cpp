#include "scene/texture_io.h"

#include "core/error.h"
#include "core/log.h"

#include <stb/stb_image.h>

#include <cstring>
#include <memory>
#include <system_error>

namespace glint {
namespace {

Texture checker_standing_in_for(const std::filesystem::path& path) {
  Texture texture = make_checker_texture();
  texture.name = path.string();  // says which file is missing; placeholder = true says it is a checker
  return texture;
}

}  // namespace

Texture load_texture_or_placeholder(const std::filesystem::path& path, std::string_view referenced_by) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    log_warning("{}: texture '{}' not found; using a checker placeholder", referenced_by, path.string());
    return checker_standing_in_for(path);
  }
  // stb's flip flag is process-wide state; pin it for this thread so that rows always come top row
  // first, the convention of scene.h, whatever another caller set.
  stbi_set_flip_vertically_on_load_thread(0);
  int width = 0, height = 0, channels_in_file = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load(path.c_str(), &width, &height, &channels_in_file, 4), &stbi_image_free);
  if (!pixels) {
    log_warning("{}: texture '{}' cannot be read ({}); using a checker placeholder", referenced_by, path.string(),
                stbi_failure_reason());
    return checker_standing_in_for(path);
  }
  Texture texture;
  texture.name = path.string();
  texture.width = width;
  texture.height = height;
  const std::size_t bytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4;
  texture.rgba.assign(pixels.get(), pixels.get() + bytes);
  return texture;
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
