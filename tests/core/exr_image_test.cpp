// core/exr_image.h: linear float EXRs written whole (temporary + rename) and read back exactly, and
// every unreadable file as one error naming it.
#include "core/exr_image.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

// Values a half could not hold (HDR above 65504, tiny, many significant bits), negatives and zero.
ImageRgbaF known_linear_image() {
  ImageRgbaF image(7, 5);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      image.at(x, y) = glm::vec4(0.1f * static_cast<float>(x) + 1e-7f * static_cast<float>(y),
                                 100000.0f + static_cast<float>(x * y) / 3.0f, -0.333333f * static_cast<float>(y),
                                 0.25f);  // alpha is not stored
  image.at(0, 0) = glm::vec4(0.0f, 1.0f / 3.0f, std::numeric_limits<float>::min(), 0.0f);
  return image;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

TEST(ExrImage, RoundTripOfFloatRgbIsExactWithAlphaOneAndTextAttributes) {
  const TempFolder folder;
  const fs::path path = folder.path() / "frame.exr";
  const ImageRgbaF image = known_linear_image();
  write_exr(path, image, {{"glintToneMap", "reinhard"}, {"note", "a b c"}});

  const ExrFile read = read_exr(path);
  ASSERT_EQ(read.image.width, 7);
  ASSERT_EQ(read.image.height, 5);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const glm::vec4 expected(glm::vec3(image.at(x, y)), 1.0f);
      EXPECT_EQ(read.image.at(x, y), expected) << x << "," << y;  // bit for bit: FLOAT channels
    }
  EXPECT_EQ(read.text.at("glintToneMap"), "reinhard");
  EXPECT_EQ(read.text.at("note"), "a b c");
  EXPECT_TRUE(has_exr_signature(path));
  // Nothing but the file: the temporary was renamed onto it.
  EXPECT_EQ(std::distance(fs::directory_iterator(folder.path()), fs::directory_iterator()), 1);
}

TEST(ExrImage, UnwritableFolderIsAnErrorNamingTheFile) {
  const TempFolder folder;
  const fs::path path = folder.path() / "missing" / "frame.exr";
  const std::string message = error_of([&] { write_exr(path, known_linear_image()); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(path));
}

TEST(ExrImage, MissingNonExrTruncatedAndMalformedFilesAreOneLineErrorsNamingTheFile) {
  const TempFolder folder;
  const fs::path good = folder.path() / "good.exr";
  write_exr(good, known_linear_image());
  const std::string bytes = file_bytes(good);
  // The magic number and version, then garbage where the header's attributes should be.
  std::string scrambled = bytes.substr(0, 8);
  scrambled += std::string(200, '\x7f');
  const struct {
    fs::path path;
    std::string reason;
  } cases[] = {
      {folder.path() / "absent.exr", "no such file"},
      {folder.write("text.exr", "not an image at all\n"), "not an EXR file"},
      {folder.write("png.exr", "\x89PNG\r\n\x1a\n0000"), "not an EXR file"},
      {folder.write("truncated.exr", std::string_view(bytes).substr(0, bytes.size() / 2)), ""},
      {folder.write("header-only.exr", std::string_view(bytes).substr(0, 40)), ""},
      {folder.write("scrambled.exr", scrambled), ""},
  };
  for (const auto& bad : cases) {
    const std::string message = error_of([&] { (void)read_exr(bad.path); });
    EXPECT_NE(message.find("cannot read EXR '" + bad.path.string() + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(bad.reason), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace glint::testing
