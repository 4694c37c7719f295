#include "core/untrusted_text.h"

#include <fmt/format.h>

#include <algorithm>

namespace glint {
namespace {

// Length of the valid UTF-8 sequence starting at text[i] (1 to 4), or 0 when it is not valid
// (overlong forms, surrogates and code points above U+10FFFF are invalid too).
std::size_t utf8_sequence_length(std::string_view text, std::size_t i, char32_t& code_point) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  std::size_t length = 0;
  char32_t minimum = 0;
  if (lead < 0x80) {
    code_point = lead;
    return 1;
  }
  if ((lead & 0xE0) == 0xC0) { length = 2; code_point = lead & 0x1Fu; minimum = 0x80; }
  else if ((lead & 0xF0) == 0xE0) { length = 3; code_point = lead & 0x0Fu; minimum = 0x800; }
  else if ((lead & 0xF8) == 0xF0) { length = 4; code_point = lead & 0x07u; minimum = 0x10000; }
  else return 0;
  if (i + length > text.size()) return 0;
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code_point = (code_point << 6) | (byte(i + k) & 0x3Fu);
  }
  if (code_point < minimum || code_point > 0x10FFFF || (code_point >= 0xD800 && code_point <= 0xDFFF)) return 0;
  return length;
}

}  // namespace

std::string untrusted_text(std::string_view text) {
  std::string out;
  out.reserve(std::min(text.size(), kUntrustedTextMaxBytes) + 32);
  std::size_t i = 0;
  while (i < text.size()) {
    char32_t code_point = 0;
    const std::size_t length = utf8_sequence_length(text, i, code_point);
    std::string piece;
    if (length == 0) piece = fmt::format("\\x{:02x}", static_cast<unsigned char>(text[i]));
    else if (code_point == '\n') piece = "\\n";
    else if (code_point == '\t') piece = "\\t";
    else if (code_point == '\r') piece = "\\r";
    else if (code_point == '\\') piece = "\\\\";
    else if (code_point < 0x20 || code_point == 0x7F) piece = fmt::format("\\x{:02x}", static_cast<unsigned>(code_point));
    else if (code_point >= 0x80 && code_point <= 0x9F) piece = fmt::format("\\u{:04x}", static_cast<unsigned>(code_point));
    else piece = std::string(text.substr(i, length));
    if (out.size() + piece.size() > kUntrustedTextMaxBytes) {
      out += fmt::format("... ({} bytes in all)", text.size());
      return out;
    }
    out += piece;
    i += length == 0 ? 1 : length;
  }
  return out;
}

}  // namespace glint
