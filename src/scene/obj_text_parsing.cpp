#include "scene/obj_text_parsing.h"

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <system_error>

namespace glint::obj_text {
namespace {

bool has_plus_sign(std::string_view token) {
  return token.size() > 1 && token[0] == '+' && token[1] != '+' && token[1] != '-';
}

}  // namespace

bool LineReader::next(std::string_view& line) {
  if (finished_) return false;
  const void* newline = std::memchr(rest_.data(), '\n', rest_.size());
  if (newline == nullptr) {
    line = rest_;
    finished_ = true;
    // A final newline leaves an empty remainder: that is not an extra line.
    if (line.empty()) return false;
  } else {
    const std::size_t length = static_cast<std::size_t>(static_cast<const char*>(newline) - rest_.data());
    line = rest_.substr(0, length);
    rest_.remove_prefix(length + 1);
  }
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  ++line_number_;
  return true;
}

std::string_view trim(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string_view take_token(std::string_view& text) {
  std::size_t begin = 0;
  while (begin < text.size() && is_blank(text[begin])) ++begin;
  std::size_t end = begin;
  while (end < text.size() && !is_blank(text[end])) ++end;
  const std::string_view token = text.substr(begin, end - begin);
  text.remove_prefix(end);
  return token;
}

std::optional<float> parse_float(std::string_view token) {
  // from_chars does not accept the leading '+' that some exporters write.
  if (has_plus_sign(token)) token.remove_prefix(1);
  if (token.empty()) return std::nullopt;
  double value = 0.0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (end != token.data() + token.size()) return std::nullopt;
  if (error == std::errc::result_out_of_range) {
    // Overflow or underflow: the exponent's sign tells which.
    const std::size_t exponent = token.find_first_of("eE");
    const bool underflow = exponent != std::string_view::npos && exponent + 1 < token.size() && token[exponent + 1] == '-';
    if (underflow) return 0.0f;
    return token.front() == '-' ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity();
  }
  if (error != std::errc()) return std::nullopt;
  if (std::isfinite(value) && std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max()))
    return value < 0.0 ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity();
  return static_cast<float>(value);
}

std::optional<long long> parse_integer(std::string_view token) {
  if (has_plus_sign(token)) token.remove_prefix(1);
  long long value = 0;
  const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
  if (error != std::errc() || end != token.data() + token.size() || token.empty()) return std::nullopt;
  return value;
}

}  // namespace glint::obj_text
