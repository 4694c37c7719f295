#include "scene/jpeg_huffman_check.h"

#include "core/error.h"

#include <cstddef>

namespace glint {
namespace {

constexpr unsigned char kDefineHuffmanTables = 0xC4;
constexpr unsigned char kStartOfScan = 0xDA;
constexpr unsigned char kEndOfImage = 0xD9;

// Reads bytes as stb_image's stbi__get8 does: past the end, every byte is 0.
class ByteCursor {
public:
  explicit ByteCursor(std::span<const unsigned char> bytes) : bytes_(bytes) {}
  bool at_end() const { return position_ >= bytes_.size(); }
  std::size_t position() const { return position_; }
  unsigned char next() { return at_end() ? 0 : bytes_[position_++]; }
  unsigned peek(std::size_t ahead) const {
    return position_ + ahead < bytes_.size() ? bytes_[position_ + ahead] : 0u;
  }
  int next16() {
    const int high = next();
    return (high << 8) | next();
  }
  void skip(std::size_t count) { position_ += count; }

private:
  std::span<const unsigned char> bytes_;
  std::size_t position_ = 0;
};

// The next marker code as stb_image finds it between segments: bytes up to a 0xFF are skipped, fill
// bytes (0xFF) too. 0 at the end of the data.
unsigned char next_marker(ByteCursor& cursor) {
  while (!cursor.at_end()) {
    if (cursor.next() != 0xFF) continue;
    unsigned char code = cursor.next();
    while (code == 0xFF && !cursor.at_end()) code = cursor.next();
    if (code != 0) return code;
  }
  return 0;
}

// After a scan's header: its entropy-coded data runs up to the first marker that is neither a stuffed
// zero (FF 00) nor a restart marker (FF D0..D7), which the decoder consumes inside the scan.
void skip_entropy_coded_data(ByteCursor& cursor) {
  while (!cursor.at_end()) {
    if (cursor.peek(0) == 0xFF) {
      const unsigned code = cursor.peek(1);
      if (code != 0x00 && code != 0xFF && (code < 0xD0 || code > 0xD7)) return;
      cursor.skip(code == 0xFF ? 1 : 2);
    } else {
      cursor.skip(1);
    }
  }
}

// A DHT segment, read like stbi__process_marker reads it: tables follow each other while the segment
// length is not used up, each a class/slot byte, 16 code counts and the codes' values.
void check_huffman_segment(ByteCursor& cursor, std::size_t segment_start) {
  int remaining = cursor.next16() - 2;
  while (remaining > 0) {
    const unsigned char slot = cursor.next();
    if ((slot >> 4) > 1 || (slot & 15) > 3) return;  // stb_image rejects the file here
    int codes = 0;
    for (int length = 0; length < 16; ++length) codes += cursor.next();
    if (codes > 256)
      fail("the JPEG's Huffman table segment at byte {} declares {} codes in one table (at most 256)", segment_start,
           codes);
    cursor.skip(static_cast<std::size_t>(codes));
    remaining -= 17 + codes;
  }
}

}  // namespace

void check_jpeg_huffman_tables(std::span<const unsigned char> jpeg) {
  ByteCursor cursor(jpeg);
  // stb_image takes any file that starts with FF, more fill bytes FF, then D8 (start of image).
  if (cursor.next() != 0xFF) return;
  unsigned char start = cursor.next();
  while (start == 0xFF && !cursor.at_end()) start = cursor.next();
  if (start != 0xD8) return;  // not a JPEG: stb_image's JPEG reader declines it
  while (!cursor.at_end()) {
    const std::size_t marker_start = cursor.position();
    const unsigned char marker = next_marker(cursor);
    if (marker == 0 || marker == kEndOfImage) return;
    if (marker >= 0xD0 && marker <= 0xD7) continue;  // a restart marker outside a scan has no length
    if (marker == kDefineHuffmanTables) {
      check_huffman_segment(cursor, marker_start);
      continue;
    }
    // Every other segment (frame header, quantisation tables, application data, scan header) is as
    // long as its length field says; stb_image rejects those it cannot read that far.
    const int length = cursor.next16();
    if (length < 2) return;
    cursor.skip(static_cast<std::size_t>(length - 2));
    if (marker == kStartOfScan) skip_entropy_coded_data(cursor);
  }
}

}  // namespace glint
