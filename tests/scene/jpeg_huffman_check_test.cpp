#include "scene/jpeg_huffman_check.h"

#include "core/error.h"
#include "scene/texture_io.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace glint {
namespace {

using Bytes = std::vector<unsigned char>;

Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes all;
  for (const Bytes& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

// A DHT segment of one table whose 16 code counts are `counts` (values all zero).
Bytes huffman_segment(const Bytes& counts) {
  int codes = 0;
  for (unsigned char count : counts) codes += count;
  const int length = 2 + 17 + codes;
  Bytes segment(4 + 17 + static_cast<std::size_t>(codes), 0);  // table class 0, slot 0; values 0
  segment[0] = 0xFF;
  segment[1] = 0xC4;
  segment[2] = static_cast<unsigned char>(length >> 8);
  segment[3] = static_cast<unsigned char>(length & 0xFF);
  std::copy(counts.begin(), counts.end(), segment.begin() + 5);
  return segment;
}

const Bytes kStart{0xFF, 0xD8};
const Bytes kEnd{0xFF, 0xD9};
const Bytes k272Codes(16, 17);            // 16 x 17 = 272 codes: more than stb_image's 256
const Bytes k12Codes{0, 1, 5, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0};  // a real DC table's counts

TEST(JpegHuffmanCheck, ATableOfMoreThan256CodesIsAnError) {
  const std::string message = testing::error_of([&] { check_jpeg_huffman_tables(concat({kStart, huffman_segment(k272Codes), kEnd})); });
  EXPECT_NE(message.find("272 codes"), std::string::npos) << message;
  EXPECT_NE(message.find("at most 256"), std::string::npos) << message;
}

TEST(JpegHuffmanCheck, ValidTablesAndOtherFilesPass) {
  EXPECT_NO_THROW(check_jpeg_huffman_tables(concat({kStart, huffman_segment(k12Codes), kEnd})));
  EXPECT_NO_THROW(check_jpeg_huffman_tables(Bytes{0x89, 'P', 'N', 'G'}));  // not a JPEG
  EXPECT_NO_THROW(check_jpeg_huffman_tables(Bytes{}));
  EXPECT_NO_THROW(check_jpeg_huffman_tables(Bytes{0xFF, 0xD8, 0xFF}));   // cut short
}

TEST(JpegHuffmanCheck, BytesThatLookLikeATableInsideOtherSegmentsAreNotOne) {
  // An APP1 segment (e.g. EXIF) and a scan's entropy-coded data may hold FF C4 followed by anything.
  Bytes app1{0xFF, 0xE1, 0x00, 0x00};
  const Bytes fake = huffman_segment(k272Codes);
  app1.insert(app1.end(), fake.begin(), fake.end());
  app1[3] = static_cast<unsigned char>(app1.size() - 2);
  const Bytes scan_header{0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00};
  const Bytes entropy_data{0x12, 0xFF, 0x00, 0x34, 0xFF, 0xD0, 0x56};  // a stuffed FF and a restart marker
  EXPECT_NO_THROW(check_jpeg_huffman_tables(concat({kStart, app1, scan_header, entropy_data, kEnd})));
}

TEST(JpegHuffmanCheck, TablesBetweenScansAndAfterFillBytesAreChecked) {
  // stb_image skips FF fill bytes before the start marker and reads DHT segments between the scans of
  // a progressive JPEG, after the entropy-coded data.
  const Bytes scan_header{0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00};
  const Bytes entropy_data{0x12, 0xFF, 0x00, 0x34, 0xFF, 0xD3, 0x56};
  EXPECT_THROW(check_jpeg_huffman_tables(concat({Bytes{0xFF, 0xFF}, kStart, scan_header, entropy_data,
                                                 huffman_segment(k272Codes), kEnd})),
               Error);
  EXPECT_THROW(check_jpeg_huffman_tables(concat({Bytes{0xFF}, kStart, huffman_segment(k272Codes)})), Error);
}

TEST(JpegHuffmanCheck, DecodeTextureRefusesTheTableBeforeStbImageBuildsIt) {
  // Without the check, stb_image 2.27 writes the 272 code lengths past its 257-byte array.
  const Bytes jpeg = concat({kStart, huffman_segment(k272Codes), kEnd});
  const std::string message = testing::error_of([&] { decode_texture(jpeg, "bad.jpg"); });
  EXPECT_NE(message.find("Huffman table"), std::string::npos) << message;
}

}  // namespace
}  // namespace glint
