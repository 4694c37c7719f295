#include "render/texture_layers.h"

#include "core/error.h"

#define STB_IMAGE_RESIZE_IMPLEMENTATION
#include <stb/stb_image_resize.h>

#include <algorithm>
#include <cstring>

namespace glint::render {

int texture_layer_size(const std::vector<Texture>& textures, int max_size) {
  if (max_size < 1) fail("texture layers: maximum layer size {} must be at least 1", max_size);
  int largest = 1;
  for (const Texture& texture : textures) largest = std::max({largest, texture.width, texture.height});
  return std::min(largest, max_size);
}

std::vector<std::uint8_t> texture_layer_texels(const Texture& texture, int size) {
  const std::size_t expected = static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height) * 4;
  if (texture.width <= 0 || texture.height <= 0 || texture.rgba.size() != expected)
    fail("texture '{}': {}x{} texels but {} bytes of RGBA data", texture.name, texture.width, texture.height,
         texture.rgba.size());
  if (size < 1) fail("texture '{}': invalid layer size {}", texture.name, size);
  const std::size_t row_bytes = static_cast<std::size_t>(size) * 4;
  std::vector<std::uint8_t> top_first(row_bytes * static_cast<std::size_t>(size));
  if (texture.width == size && texture.height == size) {
    top_first = texture.rgba;
  } else {
    // Alpha is channel 3 and not premultiplied; sRGB colour is filtered in linear light.
    const int ok = stbir_resize_uint8_srgb(texture.rgba.data(), texture.width, texture.height, 0, top_first.data(),
                                           size, size, 0, 4, 3, 0);
    if (ok == 0) fail("texture '{}': resampling {}x{} to {}x{} failed", texture.name, texture.width, texture.height, size, size);
  }
  // GL's first row is t = 0, which scene.h puts at the image's bottom: flip.
  std::vector<std::uint8_t> bottom_first(top_first.size());
  for (int y = 0; y < size; ++y)
    std::memcpy(&bottom_first[static_cast<std::size_t>(y) * row_bytes],
                &top_first[static_cast<std::size_t>(size - 1 - y) * row_bytes], row_bytes);
  return bottom_first;
}

}  // namespace glint::render
