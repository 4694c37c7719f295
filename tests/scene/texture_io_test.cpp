#include "scene/texture_io.h"

#include "core/error.h"
#include "core/log.h"
#include "scene/crafted_images.h"
#include "scene/png_writer.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

using testing::TempFolder;

TEST(TextureIo, LoadsPngAsRgbaTopRowFirst) {
  TempFolder folder;
  const std::filesystem::path file = folder.path() / "tiny.png";
  testing::write_png(file, 2, 2, testing::two_by_two_rgba());
  ScopedLogCapture capture;
  const Texture texture = load_texture_or_placeholder(file, "test.mtl:1");
  EXPECT_FALSE(texture.placeholder);
  EXPECT_EQ(texture.name, file.string());
  ASSERT_EQ(texture.width, 2);
  ASSERT_EQ(texture.height, 2);
  EXPECT_EQ(texture.rgba, testing::two_by_two_rgba());  // byte for byte, rows in file order
  EXPECT_TRUE(capture.entries().empty());
}

TEST(TextureIo, ExpandsRgbFilesToFourChannelsWithOpaqueAlpha) {
  TempFolder folder;
  const std::filesystem::path file = folder.path() / "rgb.bmp";
  const std::vector<std::uint8_t> rgb{10, 20, 30, 40, 50, 60};  // 2x1, 3 channels
  ASSERT_NE(stbi_write_bmp(file.c_str(), 2, 1, 3, rgb.data()), 0);
  const Texture texture = load_texture_or_placeholder(file, "test.mtl:1");
  ASSERT_EQ(texture.rgba.size(), 8u);
  EXPECT_EQ(texture.rgba, (std::vector<std::uint8_t>{10, 20, 30, 255, 40, 50, 60, 255}));
}

TEST(TextureIo, LoadsJpegAndTga) {
  TempFolder folder;
  std::vector<std::uint8_t> grey(8 * 8 * 4, 128);
  for (std::size_t i = 3; i < grey.size(); i += 4) grey[i] = 255;
  ASSERT_NE(stbi_write_jpg((folder.path() / "grey.jpg").c_str(), 8, 8, 4, grey.data(), 95), 0);
  ASSERT_NE(stbi_write_tga((folder.path() / "grey.tga").c_str(), 8, 8, 4, grey.data()), 0);
  for (const char* name : {"grey.jpg", "grey.tga"}) {
    const Texture texture = load_texture_or_placeholder(folder.path() / name, "test.mtl:1");
    EXPECT_FALSE(texture.placeholder) << name;
    ASSERT_EQ(texture.rgba.size(), grey.size()) << name;
    // JPEG is lossy: a flat grey comes back within a few levels.
    EXPECT_NEAR(texture.rgba[0], 128, 3) << name;
    EXPECT_EQ(texture.rgba[3], 255) << name;
  }
}

TEST(TextureIo, MissingFileGivesCheckerAndWarningNamingTheReference) {
  TempFolder folder;
  ScopedLogCapture capture;
  const Texture texture = load_texture_or_placeholder(folder.path() / "absent.png", "walls.mtl:12");
  EXPECT_TRUE(texture.placeholder);
  EXPECT_GT(texture.width, 0);
  EXPECT_EQ(texture.rgba.size(), static_cast<std::size_t>(texture.width * texture.height * 4));
  EXPECT_EQ(capture.count_warnings("walls.mtl:12"), 1);
  EXPECT_EQ(capture.count_warnings("absent.png"), 1);
}

TEST(TextureIo, UndecodableFileGivesCheckerAndWarning) {
  TempFolder folder;
  const std::filesystem::path file = folder.write("broken.png", "this is not a PNG");
  ScopedLogCapture capture;
  const Texture texture = load_texture_or_placeholder(file, "walls.mtl:3");
  EXPECT_TRUE(texture.placeholder);
  EXPECT_EQ(capture.count_warnings("cannot be read"), 1);
  EXPECT_EQ(capture.count_warnings("walls.mtl:3"), 1);
}

TEST(TextureIo, ATinyJpegDeclaringAHugeImageIsRefusedFromItsHeader) {
  // 248 bytes that declare 20000 x 20000: glint allocated 1.6 GB (3.1 GB in all) before finding the
  // data short. The limit is read from the header, before decoding, the same for every format.
  TempFolder folder;
  const std::filesystem::path jpeg = folder.write("huge.jpg", testing::jpeg_declaring(20000, 20000));
  ScopedLogCapture capture;
  EXPECT_TRUE(load_texture_or_placeholder(jpeg, "walls.mtl:7").placeholder);
  EXPECT_EQ(capture.count_warnings("walls.mtl:7: texture '" + jpeg.string() + "' cannot be read: the JPEG header "
                                   "declares 20000 x 20000 texels, more than glint's limit of 268435456 texels"),
            1);
  // The same limit for a PNG: an RGB one of 20000 x 14000 passes stb_image's own PNG bound (2^30
  // bytes of 3 channels) but not glint's (its IHDR patched; stb_image does not check PNG CRCs).
  std::vector<std::uint8_t> png;
  const std::vector<std::uint8_t> rgb(2 * 2 * 3, 200);
  stbi_write_png_to_func([](void* out, void* data, int size) {
    auto* bytes = static_cast<std::uint8_t*>(data);
    static_cast<std::vector<std::uint8_t>*>(out)->insert(static_cast<std::vector<std::uint8_t>*>(out)->end(), bytes, bytes + size);
  }, &png, 2, 2, 3, rgb.data(), 6);
  const auto put_be32 = [&png](std::size_t at, std::uint32_t value) {
    for (std::size_t i = 0; i < 4; ++i) png[at + i] = static_cast<std::uint8_t>(value >> (24 - 8 * i));
  };
  put_be32(16, 20000);  // IHDR width, after the 8-byte signature and the chunk's length and type
  put_be32(20, 14000);  // IHDR height
  EXPECT_TRUE(load_texture_or_placeholder(folder.write("huge.png", png), "walls.mtl:8").placeholder);
  EXPECT_EQ(capture.count_warnings("the PNG header declares 20000 x 14000 texels, more than glint's limit"), 1);
}

TEST(TextureIo, WarningsGiveAReadableReasonForTheFilesFormat) {
  TempFolder folder;
  std::vector<std::uint8_t> damaged = testing::jpeg_declaring(8, 8);
  damaged.resize(damaged.size() / 2);  // the entropy-coded data cut short
  ScopedLogCapture capture;
  load_texture_or_placeholder(folder.write("cut.jpg", damaged), "a.mtl:1");
  load_texture_or_placeholder(folder.write("text.png", "not an image at all"), "a.mtl:2");
  load_texture_or_placeholder(folder.write("empty.png", ""), "a.mtl:3");
  ASSERT_EQ(capture.entries().size(), 3u);
  EXPECT_NE(capture.entries()[0].message.find("cut.jpg' cannot be read: the JPEG data is damaged"), std::string::npos)
      << capture.entries()[0].message;
  EXPECT_NE(capture.entries()[1].message.find("text.png' cannot be read: not an image glint can read"), std::string::npos)
      << capture.entries()[1].message;
  EXPECT_NE(capture.entries()[2].message.find("empty.png' cannot be read: the file is empty"), std::string::npos)
      << capture.entries()[2].message;
  for (const auto& entry : capture.entries()) {
    EXPECT_EQ(entry.message.find("bad png sig"), std::string::npos) << entry.message;
    EXPECT_EQ(entry.message.find("()"), std::string::npos) << entry.message;
  }
}

TEST(TextureIo, CheckerAlternatesMagentaAndBlackSquares) {
  const Texture checker = make_checker_texture(16, 4);
  EXPECT_TRUE(checker.placeholder);
  ASSERT_EQ(checker.width, 16);
  ASSERT_EQ(checker.height, 16);
  ASSERT_EQ(checker.rgba.size(), 16u * 16u * 4u);
  auto texel = [&](int x, int y) { return &checker.rgba[static_cast<std::size_t>((y * 16 + x) * 4)]; };
  EXPECT_EQ(texel(0, 0)[0], 255);  // magenta
  EXPECT_EQ(texel(0, 0)[1], 0);
  EXPECT_EQ(texel(0, 0)[2], 255);
  EXPECT_EQ(texel(3, 3)[0], 255);  // same square
  EXPECT_EQ(texel(4, 0)[0], 0);    // next square along x: black
  EXPECT_EQ(texel(4, 0)[2], 0);
  EXPECT_EQ(texel(0, 4)[0], 0);    // next square along y: black
  EXPECT_EQ(texel(4, 4)[0], 255);  // diagonal: magenta again
  for (std::size_t i = 3; i < checker.rgba.size(); i += 4) ASSERT_EQ(checker.rgba[i], 255);
}

TEST(TextureIo, CheckerRejectsNonPositiveSizes) {
  EXPECT_THROW(make_checker_texture(0, 8), Error);
  EXPECT_THROW(make_checker_texture(8, 0), Error);
}

}  // namespace
}  // namespace glint
