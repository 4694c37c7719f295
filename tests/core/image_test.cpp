#include "core/error.h"
#include "core/image.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace glint {
namespace {

namespace fs = std::filesystem;

// A fresh folder per test, removed afterwards.
class ImagePng : public ::testing::Test {
protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("glint_image_test_" + std::to_string(::getpid()) + "_" +
               ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  int files_in_folder() const {
    int count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(folder_)) ++count;
    return count;
  }

  fs::path folder_;
};

// Every byte value appears in every channel, alpha included (alpha 0 must not lose the colour).
ImageRgba8 pattern_image(int width, int height) {
  ImageRgba8 image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int i = y * width + x;
      image.at(x, y) = glm::u8vec4(static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i * 7 + 3),
                                   static_cast<std::uint8_t>(255 - i), static_cast<std::uint8_t>(i * 13));
    }
  return image;
}

TEST(Image, AtAddressesRowsTopFirst) {
  ImageRgba8 image(3, 2);
  image.at(2, 1) = glm::u8vec4(9, 8, 7, 6);
  EXPECT_EQ(image.pixels[1 * 3 + 2], glm::u8vec4(9, 8, 7, 6));
  EXPECT_EQ(image.pixels.size(), 6u);
}

TEST(Image, QuantizeClampsAndRoundsToNearest) {
  ImageRgbaF image(2, 1);
  image.at(0, 0) = glm::vec4(-0.5f, 0.0f, 1.0f, 2.0f);
  image.at(1, 0) = glm::vec4(0.2f, 0.5f, 100.0f / 255.0f, (100.4f) / 255.0f);
  const ImageRgba8 bytes = quantize_to_rgba8(image);
  EXPECT_EQ(bytes.at(0, 0), glm::u8vec4(0, 0, 255, 255));
  EXPECT_EQ(bytes.at(1, 0), glm::u8vec4(51, 128, 100, 100));
}

TEST_F(ImagePng, RoundTripIsBitExact) {
  const ImageRgba8 image = pattern_image(37, 23);  // odd sizes: no row padding assumptions
  const fs::path path = folder_ / "pattern.png";
  write_png(path, image);
  const ImageRgba8 back = read_png(path);
  ASSERT_EQ(back.width, 37);
  ASSERT_EQ(back.height, 23);
  EXPECT_EQ(back.pixels, image.pixels);
  EXPECT_EQ(files_in_folder(), 1);  // the temporary was renamed, not left beside it
}

TEST_F(ImagePng, OverwritingReplacesTheOldImage) {
  const fs::path path = folder_ / "frame.png";
  write_png(path, pattern_image(4, 4));
  const ImageRgba8 second(5, 3, glm::u8vec4(1, 2, 3, 4));
  write_png(path, second);
  EXPECT_EQ(read_png(path).pixels, second.pixels);
  EXPECT_EQ(files_in_folder(), 1);
}

TEST_F(ImagePng, WritingIntoAMissingFolderNamesThePathAndLeavesNoFile) {
  const fs::path path = folder_ / "missing" / "frame.png";
  try {
    write_png(path, pattern_image(4, 4));
    FAIL() << "expected a glint::Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("does not exist"), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(folder_ / "missing"));
  EXPECT_EQ(files_in_folder(), 0);
}

TEST_F(ImagePng, FailedRenameRemovesTheTemporary) {
  // A folder already sits where the PNG should go: encoding and writing succeed, the rename fails.
  const fs::path path = folder_ / "taken.png";
  fs::create_directory(path);
  try {
    write_png(path, pattern_image(4, 4));
    FAIL() << "expected a glint::Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
  }
  EXPECT_TRUE(fs::is_directory(path));
  EXPECT_EQ(files_in_folder(), 1);  // only the folder: no *.tmp-* left behind
}

TEST_F(ImagePng, EmptyImageIsRejected) {
  EXPECT_THROW(write_png(folder_ / "empty.png", ImageRgba8{}), Error);
  EXPECT_EQ(files_in_folder(), 0);
}

TEST_F(ImagePng, ReadingAMissingFileNamesThePath) {
  const fs::path path = folder_ / "nothing.png";
  try {
    read_png(path);
    FAIL() << "expected a glint::Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
  }
}

TEST_F(ImagePng, ReadingANonImageNamesThePath) {
  const fs::path path = folder_ / "text.png";
  std::ofstream(path) << "not a png\n";
  try {
    read_png(path);
    FAIL() << "expected a glint::Error";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(path.string()), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace glint
