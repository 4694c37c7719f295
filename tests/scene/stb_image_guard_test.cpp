#include "scene/stb_image_guard.h"

#include "core/error.h"
#include "scene/texture_io.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string_view>
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

TEST(StbImageGuard, ATableOfMoreThan256CodesIsAnError) {
  const std::string message = testing::error_of([&] { check_before_stb_image(concat({kStart, huffman_segment(k272Codes), kEnd})); });
  EXPECT_NE(message.find("272 codes"), std::string::npos) << message;
  EXPECT_NE(message.find("at most 256"), std::string::npos) << message;
}

TEST(StbImageGuard, ValidTablesAndOtherFilesPass) {
  EXPECT_NO_THROW(check_before_stb_image(concat({kStart, huffman_segment(k12Codes), kEnd})));
  EXPECT_NO_THROW(check_before_stb_image(Bytes{0x89, 'P', 'N', 'G'}));  // not a JPEG
  EXPECT_NO_THROW(check_before_stb_image(Bytes{}));
  EXPECT_NO_THROW(check_before_stb_image(Bytes{0xFF, 0xD8, 0xFF}));   // cut short
}

TEST(StbImageGuard, BytesThatLookLikeATableInsideOtherSegmentsAreNotOne) {
  // An APP1 segment (e.g. EXIF) and a scan's entropy-coded data may hold FF C4 followed by anything.
  Bytes app1{0xFF, 0xE1, 0x00, 0x00};
  const Bytes fake = huffman_segment(k272Codes);
  app1.insert(app1.end(), fake.begin(), fake.end());
  app1[3] = static_cast<unsigned char>(app1.size() - 2);
  const Bytes scan_header{0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00};
  const Bytes entropy_data{0x12, 0xFF, 0x00, 0x34, 0xFF, 0xD0, 0x56};  // a stuffed FF and a restart marker
  Bytes ac_table = huffman_segment(k12Codes);
  ac_table[4] = 0x10;  // class AC, slot 0
  EXPECT_NO_THROW(check_before_stb_image(concat({kStart, app1, huffman_segment(k12Codes), ac_table, scan_header, entropy_data, kEnd})));
}

TEST(StbImageGuard, TablesBetweenScansAndAfterFillBytesAreChecked) {
  // stb_image skips FF fill bytes before the start marker and reads DHT segments between the scans of
  // a progressive JPEG, after the entropy-coded data.
  const Bytes scan_header{0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, 0x00, 0x00, 0x3F, 0x00};
  const Bytes entropy_data{0x12, 0xFF, 0x00, 0x34, 0xFF, 0xD3, 0x56};
  Bytes ac_table = huffman_segment(k12Codes);
  ac_table[4] = 0x10;  // class AC, slot 0
  const std::string message = testing::error_of([&] {
    check_before_stb_image(concat({Bytes{0xFF, 0xFF}, kStart, huffman_segment(k12Codes), ac_table, scan_header,
                                   entropy_data, huffman_segment(k272Codes), kEnd}));
  });
  EXPECT_NE(message.find("272 codes"), std::string::npos) << message;
  EXPECT_THROW(check_before_stb_image(concat({Bytes{0xFF}, kStart, huffman_segment(k272Codes)})), Error);
}

// An 8-bit DQT segment defining quantisation table `slot` (all entries 1).
Bytes quantization_table(unsigned char slot, unsigned char precision = 0) {
  const std::size_t entries = precision ? 128 : 64;
  Bytes segment(5 + entries, 1);
  const std::size_t length = 3 + entries;
  segment[0] = 0xFF;
  segment[1] = 0xDB;
  segment[2] = static_cast<unsigned char>(length >> 8);
  segment[3] = static_cast<unsigned char>(length & 0xFF);
  segment[4] = static_cast<unsigned char>(precision << 4 | slot);
  return segment;
}
const Bytes kQuantization0 = quantization_table(0);

const Bytes kBaselineFrame{0xFF, 0xC0, 0x00, 0x0B, 0x08, 0x00, 0x08, 0x00, 0x08, 0x01, 0x01, 0x11, 0x00};
const Bytes kProgressiveFrame{0xFF, 0xC2, 0x00, 0x0B, 0x08, 0x00, 0x08, 0x00, 0x08, 0x01, 0x01, 0x11, 0x00};

// A one-component scan header with DC table `dc`, AC table `ac` and the given spectral selection.
Bytes scan(unsigned char dc, unsigned char ac, unsigned char start, unsigned char end, unsigned char refinement = 0) {
  return {0xFF, 0xDA, 0x00, 0x08, 0x01, 0x01, static_cast<unsigned char>(dc << 4 | ac), start, end, refinement};
}

// A DHT segment of one table of class `table_class` in `slot` with 12 codes.
Bytes table(unsigned char table_class, unsigned char slot) {
  Bytes segment = huffman_segment(k12Codes);
  segment[4] = static_cast<unsigned char>(table_class << 4 | slot);
  return segment;
}

TEST(StbImageGuard, AScanThatDecodesWithAnUndefinedHuffmanTableIsAnError) {
  const Bytes data{0x12, 0x34};
  // Baseline: both tables of the scan must be defined.
  EXPECT_NO_THROW(check_before_stb_image(concat({kStart, kQuantization0, kBaselineFrame, table(0, 0), table(1, 0), scan(0, 0, 0, 63), data, kEnd})));
  const std::string message = testing::error_of(
      [&] { check_before_stb_image(concat({kStart, kQuantization0, kBaselineFrame, table(0, 0), scan(0, 0, 0, 63), data, kEnd})); });
  EXPECT_NE(message.find("no DHT segment defines"), std::string::npos) << message;
  EXPECT_THROW(check_before_stb_image(concat({kStart, kQuantization0, kBaselineFrame, table(0, 0), table(1, 0), scan(0, 1, 0, 63), data})), Error);
  // Progressive: a first DC scan needs only the DC table, a DC refinement none, an AC scan only the AC
  // table, and a table defined between scans counts for the scans after it.
  EXPECT_NO_THROW(check_before_stb_image(concat({kStart, kQuantization0, kProgressiveFrame, table(0, 2), scan(2, 3, 0, 0), data,
                                                 scan(3, 3, 0, 0, 0x10), data, table(1, 1), scan(0, 1, 1, 5), data, kEnd})));
  EXPECT_THROW(check_before_stb_image(concat({kStart, kQuantization0, kProgressiveFrame, table(0, 2), scan(2, 3, 0, 0), data,
                                              scan(0, 1, 1, 5), data, table(1, 1), kEnd})),
               Error);
}

TEST(StbImageGuard, AScanThatDequantisesWithAnUndefinedOrSixteenBitTableIsAnError) {
  const Bytes data{0x12, 0x34};
  const Bytes huffman = concat({table(0, 0), table(1, 0)});
  const auto error_for = [&](const Bytes& jpeg) { return testing::error_of([&] { check_before_stb_image(jpeg); }); };
  EXPECT_NO_THROW(check_before_stb_image(concat({kStart, kQuantization0, kBaselineFrame, huffman, scan(0, 0, 0, 63), data, kEnd})));
  // Baseline: the frame's component uses table 0; only table 1 is defined, or none.
  std::string message = error_for(concat({kStart, quantization_table(1), kBaselineFrame, huffman, scan(0, 0, 0, 63), data, kEnd}));
  EXPECT_NE(message.find("no DQT segment defines"), std::string::npos) << message;
  EXPECT_NE(error_for(concat({kStart, kBaselineFrame, huffman, scan(0, 0, 0, 63), data})).find("no DQT"), std::string::npos);
  // Progressive: the table may come between scans, but must exist once the last scan is read.
  EXPECT_NO_THROW(check_before_stb_image(concat({kStart, kProgressiveFrame, table(0, 0), scan(0, 0, 0, 0), data, kQuantization0, kEnd})));
  message = error_for(concat({kStart, kProgressiveFrame, table(0, 0), scan(0, 0, 0, 0), data, quantization_table(2), kEnd}));
  EXPECT_NE(message.find("no DQT segment defines"), std::string::npos) << message;
  // A 16-bit table, in any JPEG stb_image reads (8-bit samples only).
  message = error_for(concat({kStart, quantization_table(0, 1), kBaselineFrame, huffman, scan(0, 0, 0, 63), data, kEnd}));
  EXPECT_NE(message.find("16-bit table"), std::string::npos) << message;
}

TEST(StbImageGuard, APnmHeaderNumberBeyondAnIntIsAnError) {
  const auto pnm = [](std::string_view text) { return Bytes(text.begin(), text.end()); };
  EXPECT_NO_THROW(check_before_stb_image(pnm("P6\n# comment 99999999999\n2 2\n255\n")));
  EXPECT_NO_THROW(check_before_stb_image(pnm("P5 2147483647 1 255 ")));
  EXPECT_NO_THROW(check_before_stb_image(pnm("P3 99999999999 1 255 ")));  // ASCII PNM: stb_image cannot read it
  const std::string message = testing::error_of([&] { check_before_stb_image(pnm("P5 2 # x\n9999999999 255 ")); });
  EXPECT_NE(message.find("larger than 2147483647"), std::string::npos) << message;
  EXPECT_THROW(check_before_stb_image(pnm("P6 2 2 2147483648")), Error);
}

TEST(StbImageGuard, APngWhoseFirstImageDataChunkIsEmptyIsAnError) {
  const Bytes signature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  const auto chunk = [](std::string_view type, std::size_t length) {
    Bytes bytes(12 + length, 0);  // length, type, data and CRC (not checked here)
    bytes[3] = static_cast<unsigned char>(length);
    std::copy(type.begin(), type.end(), bytes.begin() + 4);
    return bytes;
  };
  const std::string message =
      testing::error_of([&] { check_before_stb_image(concat({signature, chunk("IHDR", 13), chunk("IDAT", 0), chunk("IDAT", 9)})); });
  EXPECT_NE(message.find("first image data chunk (IDAT, byte 33) is empty"), std::string::npos) << message;
  // An empty IDAT after data appends nothing to a buffer that exists.
  EXPECT_NO_THROW(check_before_stb_image(concat({signature, chunk("IHDR", 13), chunk("IDAT", 9), chunk("IDAT", 0)})));
  EXPECT_NO_THROW(check_before_stb_image(concat({signature, chunk("IHDR", 13)})));
}

TEST(StbImageGuard, DecodeTextureRefusesTheTableBeforeStbImageBuildsIt) {
  // Without the check, stb_image 2.27 writes the 272 code lengths past its 257-byte array.
  const Bytes jpeg = concat({kStart, huffman_segment(k272Codes), kEnd});
  const std::string message = testing::error_of([&] { decode_texture(jpeg, "bad.jpg"); });
  EXPECT_NE(message.find("Huffman table"), std::string::npos) << message;
}

}  // namespace
}  // namespace glint
