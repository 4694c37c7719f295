#include "app/time_limit.h"

#include <charconv>
#include <cmath>
#include <system_error>
#include <utility>

namespace glint {

double parse_time_limit_seconds(const std::string& flag, const std::string& text) {
  std::string number = text;
  double unit = 1.0;
  if (!number.empty()) {
    switch (number.back()) {
      case 's': unit = 1.0; number.pop_back(); break;
      case 'm': unit = 60.0; number.pop_back(); break;
      case 'h': unit = 3600.0; number.pop_back(); break;
      default: break;
    }
  }
  double value = 0.0;
  const char* end = number.data() + number.size();
  const auto [stop, error] = std::from_chars(number.data(), end, value);
  if (number.empty() || error != std::errc() || stop != end || !std::isfinite(value) || value < 0.0)
    fail("{}: \"{}\" is no time limit (seconds, or a number followed by s, m or h: 90, 50m, 7h)", flag, text);
  return value * unit;
}

TimeLimit::TimeLimit(std::string text, double seconds, std::chrono::steady_clock::time_point start)
    : text_(std::move(text)),
      until_(start + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds))) {}

TimeLimit TimeLimit::from_flag(const std::string& flag, const std::string& text,
                               std::chrono::steady_clock::time_point start) {
  if (text.empty()) return {};
  return TimeLimit(text, parse_time_limit_seconds(flag, text), start);
}

}  // namespace glint
