#pragma once
// Line and token helpers shared by the OBJ validation pass and the MTL reader. Both walk a file's
// text once, line by line, and need the line number for their error messages, so they work on
// string_views into the whole text instead of an istream.
#include <cstddef>
#include <optional>
#include <string_view>

namespace glint::obj_text {

// Hands out the lines of `text` one by one ('\n' separated; a trailing '\r' from Windows files is
// removed). line_number() is the 1-based number of the line last returned.
class LineReader {
public:
  explicit LineReader(std::string_view text) : rest_(text) {}
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_number_; }

private:
  std::string_view rest_;
  std::size_t line_number_ = 0;
  bool finished_ = false;
};

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view text);

// Removes the next whitespace-separated token from the front of `text` and returns it (empty when
// only blanks are left).
std::string_view take_token(std::string_view& text);

// A whole token read as a number ("1", "-2.5e3", "+.5", "nan" and "inf" included); nullopt when the
// token is not exactly one number. Values beyond float's range become +-infinity (and tiny ones 0),
// so that callers can report them as non-finite rather than as "not a number".
std::optional<float> parse_float(std::string_view token);
std::optional<long long> parse_integer(std::string_view token);

}  // namespace glint::obj_text
