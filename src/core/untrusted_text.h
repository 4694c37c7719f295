#pragma once
// Text read from a file (names, paths, keys, values) made safe to put into an error, a warning or
// run.json: a 50 MB name must not become a 50 MB line, and a control character must not reach the
// terminal raw. Every loader passes file-provided strings through untrusted_text() before it
// formats them into a message.
#include <cstddef>
#include <string>
#include <string_view>

namespace glint {

// How many bytes of an untrusted string a message keeps.
inline constexpr std::size_t kUntrustedTextMaxBytes = 256;

// `text` as printable UTF-8: control characters (C0, DEL, C1) become \n, \t, \r or \xNN (\u0080..
// \u009f for C1), bytes that are not valid UTF-8 become \xNN, and a backslash becomes \\, so the
// result can be read back without ambiguity. Longer than kUntrustedTextMaxBytes: the first part is
// kept (never split inside a character) and "... (N bytes in all)" appended. No quotes are added;
// the caller's message decides how the value is quoted.
std::string untrusted_text(std::string_view text);

}  // namespace glint
