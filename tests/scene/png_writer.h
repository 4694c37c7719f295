#pragma once
// Writes small RGBA PNGs for texture tests (stb_image_write, from the Debian libstb package).
#include <stb/stb_image_write.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <vector>

namespace glint::testing {

// `rgba` is width * height * 4 bytes, top row first.
inline void write_png(const std::filesystem::path& file, int width, int height, const std::vector<std::uint8_t>& rgba) {
  std::filesystem::create_directories(file.parent_path());
  ASSERT_NE(stbi_write_png(file.c_str(), width, height, 4, rgba.data(), width * 4), 0) << "could not write " << file;
}

// A 2x2 PNG: top row red, green; bottom row blue, half-transparent white.
inline std::vector<std::uint8_t> two_by_two_rgba() {
  return {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
}

}  // namespace glint::testing
