#include "scene/stb_image_guard.h"

#include "core/error.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <climits>
#include <cstddef>
#include <cstdint>

namespace glint {
namespace {

constexpr unsigned char kStartOfFrameBaseline = 0xC0;
constexpr unsigned char kStartOfFrameExtended = 0xC1;
constexpr unsigned char kStartOfFrameProgressive = 0xC2;
constexpr unsigned char kDefineHuffmanTables = 0xC4;
constexpr unsigned char kDefineQuantizationTables = 0xDB;
constexpr unsigned char kStartOfScan = 0xDA;
constexpr unsigned char kEndOfImage = 0xD9;

// Reads bytes as stb_image's stbi__get8 does: past the end, every byte is 0.
class ByteCursor {
public:
  explicit ByteCursor(std::span<const unsigned char> bytes) : bytes_(bytes) {}
  bool at_end() const { return position_ >= bytes_.size(); }
  std::size_t position() const { return position_; }
  unsigned char next() { return at_end() ? 0 : bytes_[position_++]; }
  unsigned peek(std::size_t ahead) const { return position_ + ahead < bytes_.size() ? bytes_[position_ + ahead] : 0u; }
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

// Which Huffman tables (DC slots 0-3, AC slots 0-3) and quantisation tables (slots 0-3) a DHT or DQT
// segment has defined so far, and the frame's components (id, quantisation slot) and whether it is
// progressive: what decides the tables a scan decodes and dequantises with.
struct FrameComponent {
  unsigned char id = 0;
  unsigned char quantization_slot = 0;
};
struct JpegState {
  std::array<std::array<bool, 4>, 2> defined{};  // [0 DC, 1 AC][slot]
  std::array<bool, 4> quantization_defined{};
  std::array<FrameComponent, 4> components{};
  unsigned component_count = 0;
  bool progressive = false;
};

// A DQT segment, read like stbi__process_marker reads it: tables of 64 entries, each a precision/slot
// byte then 8-bit (precision 0) or 16-bit (precision 1) entries. stb_image reads 8-bit samples only,
// and a JPEG of 8-bit samples may only hold 8-bit tables (ITU T.81, B.2.4.1): a 16-bit one is refused,
// because stb_image 2.27 multiplies each block's DC value by its entry in an int without an overflow
// check, and entries up to 65535 make that overflow with a single block.
void read_quantization_segment(ByteCursor& cursor, std::size_t segment_start, JpegState& state) {
  int remaining = cursor.next16() - 2;
  while (remaining > 0) {
    const unsigned char slot = cursor.next();
    const unsigned precision = slot >> 4, table_slot = slot & 15u;
    if (precision > 1 || table_slot > 3) return;  // stb_image rejects the file here
    if (precision == 1)
      fail("the JPEG's quantisation table segment at byte {} holds a 16-bit table (an 8-bit JPEG may only hold "
           "8-bit ones)",
           segment_start);
    state.quantization_defined[table_slot] = true;
    cursor.skip(64);
    remaining -= 65;
  }
}

// A frame header (SOF0-2): precision, height, width, then each component's id, sampling and
// quantisation slot.
void read_frame_header(ByteCursor& cursor, JpegState& state) {
  cursor.next16();  // length
  cursor.next();    // sample precision
  cursor.next16();  // height
  cursor.next16();  // width
  const unsigned count = cursor.next();
  state.component_count = std::min(count, 4u);
  for (unsigned i = 0; i < count; ++i) {
    const unsigned char id = cursor.next();
    cursor.next();  // sampling factors
    const unsigned char slot = cursor.next();
    if (i < state.components.size()) state.components[i] = {id, slot};
  }
}

// The quantisation table of the frame component `id` must be defined when stb_image dequantises with
// it: otherwise it reads the table from uninitialised memory (an undefined value, and an int
// overflow in stbi__jpeg_decode_block for large ones).
void check_quantization_table(unsigned char id, std::size_t segment_start, const JpegState& state) {
  for (unsigned i = 0; i < state.component_count; ++i) {
    const FrameComponent& component = state.components[i];
    if (component.id != id) continue;
    if (component.quantization_slot <= 3 && !state.quantization_defined[component.quantization_slot])
      fail("the JPEG's scan at byte {} dequantises with a quantisation table that no DQT segment defines",
           segment_start);
  }
}

// A DHT segment, read like stbi__process_marker reads it: tables follow each other while the segment
// length is not used up, each a class/slot byte, 16 code counts and the codes' values.
void read_huffman_segment(ByteCursor& cursor, std::size_t segment_start, JpegState& state) {
  int remaining = cursor.next16() - 2;
  while (remaining > 0) {
    const unsigned char slot = cursor.next();
    const unsigned table_class = slot >> 4, table_slot = slot & 15u;
    if (table_class > 1 || table_slot > 3) return;  // stb_image rejects the file here
    int codes = 0;
    for (int length = 0; length < 16; ++length) codes += cursor.next();
    if (codes > 256)
      fail("the JPEG's Huffman table segment at byte {} declares {} codes in one table (at most 256)", segment_start,
           codes);
    state.defined[table_class][table_slot] = true;
    cursor.skip(static_cast<std::size_t>(codes));
    remaining -= 17 + codes;
  }
}

// A scan header: each component names a DC and an AC table. A baseline scan decodes with both; a
// progressive one with the DC table in a first DC scan (start 0, no refinement) and with the AC table
// in an AC scan (start > 0), as stb_image does.
void check_scan_tables(ByteCursor& cursor, std::size_t segment_start, const JpegState& state) {
  const int length = cursor.next16();
  const unsigned components = cursor.next();
  std::array<unsigned char, 4> tables{}, ids{};
  for (unsigned i = 0; i < components; ++i) {
    const unsigned char id = cursor.next();
    const unsigned char table = cursor.next();
    if (i < tables.size()) {
      tables[i] = table;
      ids[i] = id;
    }
  }
  const unsigned spectral_start = cursor.next();
  cursor.next();  // spectral end
  const unsigned refinement_high = cursor.next() >> 4;
  if (components < 1 || components > 4 || length != 6 + 2 * static_cast<int>(components)) return;  // stb_image rejects it
  const bool uses_dc = !state.progressive || (spectral_start == 0 && refinement_high == 0);
  const bool uses_ac = !state.progressive || spectral_start > 0;
  for (unsigned i = 0; i < components; ++i) {
    const unsigned dc = tables[i] >> 4, ac = tables[i] & 15u;
    if (dc > 3 || ac > 3) return;  // stb_image rejects it
    if ((uses_dc && !state.defined[0][dc]) || (uses_ac && !state.defined[1][ac]))
      fail("the JPEG's scan at byte {} decodes with a Huffman table that no DHT segment defines", segment_start);
    // A baseline scan dequantises its blocks as it decodes them; a progressive JPEG dequantises every
    // component once all scans are read (checked at the end, check_jpeg).
    if (!state.progressive) check_quantization_table(ids[i], segment_start, state);
  }
}

// Walks the JPEG's marker segments the way stb_image reads them (entropy-coded data is skipped up to
// the next marker).
void check_jpeg(std::span<const unsigned char> jpeg) {
  ByteCursor cursor(jpeg);
  // stb_image takes any file that starts with FF, more fill bytes FF, then D8 (start of image).
  if (cursor.next() != 0xFF) return;
  unsigned char start = cursor.next();
  while (start == 0xFF && !cursor.at_end()) start = cursor.next();
  if (start != 0xD8) return;  // not a JPEG: stb_image's JPEG reader declines it
  JpegState state;
  // A progressive JPEG's components are dequantised after its last scan, with the tables defined by then.
  const auto check_progressive_end = [&](std::size_t end) {
    if (!state.progressive) return;
    for (unsigned i = 0; i < state.component_count; ++i) check_quantization_table(state.components[i].id, end, state);
  };
  bool scanned = false;
  while (!cursor.at_end()) {
    const std::size_t marker_start = cursor.position();
    const unsigned char marker = next_marker(cursor);
    if (marker == 0 || marker == kEndOfImage) {
      if (scanned) check_progressive_end(marker_start);
      return;
    }
    if (marker >= 0xD0 && marker <= 0xD7) continue;  // a restart marker outside a scan has no length
    if (marker == kDefineHuffmanTables) {
      read_huffman_segment(cursor, marker_start, state);
      continue;
    }
    if (marker == kDefineQuantizationTables) {
      read_quantization_segment(cursor, marker_start, state);
      continue;
    }
    if (marker == kStartOfScan) {
      ByteCursor scan_header = cursor;
      check_scan_tables(scan_header, marker_start, state);
      scanned = true;
      const int length = cursor.next16();
      if (length < 2) return;
      cursor.skip(static_cast<std::size_t>(length - 2));
      skip_entropy_coded_data(cursor);
      continue;
    }
    if (marker == kStartOfFrameProgressive) state.progressive = true;
    if (marker == kStartOfFrameBaseline || marker == kStartOfFrameExtended || marker == kStartOfFrameProgressive) {
      ByteCursor frame_header = cursor;
      read_frame_header(frame_header, state);
    }
    // Every other segment (frame header, application data) is as long as its length field says;
    // stb_image rejects those it cannot read that far.
    const int length = cursor.next16();
    if (length < 2) return;
    cursor.skip(static_cast<std::size_t>(length - 2));
  }
  if (scanned) check_progressive_end(cursor.position());
}

// A binary PNM's header (P5 or P6, then width, height and maximum value, separated by whitespace and
// # comments): each number must fit in an int.
void check_pnm_header(std::span<const unsigned char> pnm) {
  if (pnm.size() < 2 || pnm[0] != 'P' || (pnm[1] != '5' && pnm[1] != '6')) return;
  const auto is_space = [](unsigned char c) { return c == ' ' || (c >= '\t' && c <= '\r'); };
  std::size_t i = 2;
  for (int number = 0; number < 3; ++number) {
    while (i < pnm.size() && (is_space(pnm[i]) || pnm[i] == '#')) {
      if (pnm[i] == '#')
        while (i < pnm.size() && pnm[i] != '\n' && pnm[i] != '\r') ++i;
      else
        ++i;
    }
    std::int64_t value = 0;
    for (; i < pnm.size() && pnm[i] >= '0' && pnm[i] <= '9'; ++i) {
      value = value * 10 + (pnm[i] - '0');
      if (value > INT_MAX) fail("the PNM header's number at byte {} is larger than {}", i, INT_MAX);
    }
  }
}

// A PNG's chunks up to its first image data chunk (IDAT): an empty one there makes stb_image copy
// zero bytes to a null buffer (undefined behaviour; later IDATs append to a buffer that exists).
void check_png_first_image_data(std::span<const unsigned char> png) {
  static constexpr unsigned char kSignature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (png.size() < sizeof kSignature || !std::equal(std::begin(kSignature), std::end(kSignature), png.begin())) return;
  for (std::size_t at = sizeof kSignature; at + 8 <= png.size();) {
    const std::uint32_t length = std::uint32_t{png[at]} << 24 | std::uint32_t{png[at + 1]} << 16 |
                                 std::uint32_t{png[at + 2]} << 8 | std::uint32_t{png[at + 3]};
    if (png[at + 4] == 'I' && png[at + 5] == 'D' && png[at + 6] == 'A' && png[at + 7] == 'T') {
      if (length == 0) fail("the PNG's first image data chunk (IDAT, byte {}) is empty", at);
      return;
    }
    at += 12 + static_cast<std::size_t>(length);  // length, type, data, CRC
  }
}

}  // namespace

void check_before_stb_image(std::span<const unsigned char> encoded) {
  check_jpeg(encoded);
  check_pnm_header(encoded);
  check_png_first_image_data(encoded);
}

}  // namespace glint
