#include "core/image.h"

#include "core/error.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>  // implementation lives in libstb.so; never define *_IMPLEMENTATION here

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <system_error>

namespace glint {
namespace {

void append_bytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<unsigned char>*>(context);
  const auto* begin = static_cast<const unsigned char*>(data);
  bytes->insert(bytes->end(), begin, begin + size);
}

// A name no other writer (thread or process) uses at the same time, next to the final file so that
// the rename stays within one file system and is atomic.
std::filesystem::path temporary_path_for(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  return temporary;
}

void write_file_bytes(const std::filesystem::path& file, const std::vector<unsigned char>& bytes,
                      const std::filesystem::path& shown) {
  std::FILE* stream = std::fopen(file.c_str(), "wb");
  if (stream == nullptr) fail("cannot write PNG '{}': {}", shown.string(), std::strerror(errno));
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), stream) == bytes.size();
  const int write_errno = errno;
  // fclose flushes, so it is where a full disk shows up.
  const bool closed = std::fclose(stream) == 0;
  if (!written || !closed) {
    std::error_code ignored;
    std::filesystem::remove(file, ignored);
    fail("cannot write PNG '{}': {}", shown.string(), std::strerror(written ? errno : write_errno));
  }
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
  const std::filesystem::path folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    fail("cannot write PNG '{}': folder '{}' does not exist", path.string(), folder.string());

  std::vector<unsigned char> encoded;
  if (stbi_write_png_to_func(append_bytes, &encoded, image.width, image.height, 4, image.pixels.data(),
                             image.width * 4) == 0)
    fail("cannot write PNG '{}': PNG encoding failed", path.string());

  const std::filesystem::path temporary = temporary_path_for(path);
  write_file_bytes(temporary, encoded, path);
  std::filesystem::rename(temporary, path, error);
  if (error) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    fail("cannot write PNG '{}': {}", path.string(), error.message());
  }
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
