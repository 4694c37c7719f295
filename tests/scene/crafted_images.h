#pragma once
// Image files crafted for the loaders' hostile-input tests.
#include <stb/stb_image_write.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace glint::testing {

// A real 8x8 JPEG whose frame header (SOF0) is patched to declare width x height.
inline std::vector<std::uint8_t> jpeg_declaring(int width, int height) {
  std::vector<std::uint8_t> jpeg;
  std::vector<std::uint8_t> grey(8 * 8 * 3, 128);
  stbi_write_jpg_to_func([](void* out, void* data, int size) {
    auto* bytes = static_cast<std::uint8_t*>(data);
    static_cast<std::vector<std::uint8_t>*>(out)->insert(static_cast<std::vector<std::uint8_t>*>(out)->end(), bytes, bytes + size);
  }, &jpeg, 8, 8, 3, grey.data(), 90);
  for (std::size_t i = 0; i + 8 < jpeg.size(); ++i)
    if (jpeg[i] == 0xFF && jpeg[i + 1] == 0xC0) {  // FF C0, length (2), precision (1), height (2), width (2)
      jpeg[i + 5] = static_cast<std::uint8_t>(height >> 8);
      jpeg[i + 6] = static_cast<std::uint8_t>(height & 0xFF);
      jpeg[i + 7] = static_cast<std::uint8_t>(width >> 8);
      jpeg[i + 8] = static_cast<std::uint8_t>(width & 0xFF);
      return jpeg;
    }
  ADD_FAILURE() << "no SOF0 marker in the JPEG";
  return jpeg;
}

}  // namespace glint::testing
