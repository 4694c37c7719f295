#pragma once
// In-memory RGBA images, top row first (the order PNG files and screens use; GL's readback is
// bottom-first and gets flipped by the readback helpers), and PNG files.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace glint {

template <typename Pixel>
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Pixel> pixels;  // width * height, row by row, top row first

  Image() = default;
  Image(int w, int h, Pixel fill = Pixel(0))
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

  Pixel& at(int x, int y) { return pixels[index(x, y)]; }
  const Pixel& at(int x, int y) const { return pixels[index(x, y)]; }

private:
  std::size_t index(int x, int y) const {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
  }
};

using ImageRgba8 = Image<glm::u8vec4>;  // 8 bits per channel, as stored in PNG files
using ImageRgbaF = Image<glm::vec4>;    // linear float, as rendered
static_assert(sizeof(glm::u8vec4) == 4, "ImageRgba8 pixels must be tightly packed for PNG I/O");

// Clamps to [0, 1] and rounds to 8 bits per channel (no colour-space conversion: tone mapping and
// sRGB encoding are the renderer's job).
ImageRgba8 quantize_to_rgba8(const ImageRgbaF& image);

// Writes an 8-bit RGBA PNG. It is written to a temporary file in the same folder and renamed, so a
// crash never leaves a half-written PNG under `path`. A missing or unwritable folder is a
// glint::Error naming the path.
void write_png(const std::filesystem::path& path, const ImageRgba8& image);

// Reads any PNG as 8-bit RGBA (grey and RGB get full alpha, 16-bit is reduced to 8).
ImageRgba8 read_png(const std::filesystem::path& path);

}  // namespace glint
