#include "core/image.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>  // implementation lives in libstb.so; never define *_IMPLEMENTATION here

#include <cmath>
#include <cstring>
#include <memory>
#include <string_view>
#include <system_error>
#include <vector>

namespace glint {
namespace {

void append_bytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<unsigned char>*>(context);
  const auto* begin = static_cast<const unsigned char*>(data);
  bytes->insert(bytes->end(), begin, begin + size);
}

}  // namespace

ImageRgba8 quantize_to_rgba8(const ImageRgbaF& image) {
  ImageRgba8 result(image.width, image.height);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const glm::vec4 scaled = glm::clamp(image.pixels[i], 0.0f, 1.0f) * 255.0f + 0.5f;
    result.pixels[i] = glm::u8vec4(glm::floor(scaled));
  }
  return result;
}

void write_png(const std::filesystem::path& path, const ImageRgba8& image) {
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    fail("cannot write PNG '{}': image is {}x{} with {} pixels", path.string(), image.width, image.height,
         image.pixels.size());
  std::vector<unsigned char> encoded;
  if (stbi_write_png_to_func(append_bytes, &encoded, image.width, image.height, 4, image.pixels.data(),
                             image.width * 4) == 0)
    fail("cannot write PNG '{}': PNG encoding failed", path.string());
  // Encoded in memory first, so the file on disk is either the whole PNG or nothing (temp + rename).
  write_file_atomically(path, std::string_view(reinterpret_cast<const char*>(encoded.data()), encoded.size()));
}

ImageRgba8 read_png(const std::filesystem::path& path) {
  int width = 0, height = 0, channels = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> data(stbi_load(path.c_str(), &width, &height, &channels, 4),
                                                       stbi_image_free);
  if (!data) {
    std::error_code error;
    if (!std::filesystem::exists(path, error)) fail("cannot read PNG '{}': no such file", path.string());
    fail("cannot read PNG '{}': {}", path.string(), stbi_failure_reason());
  }
  ImageRgba8 image(width, height);
  std::memcpy(image.pixels.data(), data.get(), image.pixels.size() * sizeof(glm::u8vec4));
  return image;
}

}  // namespace glint
