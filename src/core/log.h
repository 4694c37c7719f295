#pragma once
// Minimal logging to stderr: warnings always, info and debug when the level is lowered (--verbose).
// Tests capture messages with ScopedLogCapture to assert that a warning was issued.
#include <fmt/format.h>

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

enum class LogLevel { debug, info, warning, error };

void set_log_level(LogLevel minimum);  // messages below this level are dropped (default: warning)
LogLevel log_level();
void log_message(LogLevel level, std::string_view message);

template <typename... Args>
void log_info(fmt::format_string<Args...> format, Args&&... args) {
  if (log_level() <= LogLevel::info) log_message(LogLevel::info, fmt::format(format, std::forward<Args>(args)...));
}
template <typename... Args>
void log_debug(fmt::format_string<Args...> format, Args&&... args) {
  if (log_level() <= LogLevel::debug) log_message(LogLevel::debug, fmt::format(format, std::forward<Args>(args)...));
}
template <typename... Args>
void log_warning(fmt::format_string<Args...> format, Args&&... args) {
  log_message(LogLevel::warning, fmt::format(format, std::forward<Args>(args)...));
}

// While alive, every message (of any level) is recorded here instead of printed.
class ScopedLogCapture {
public:
  struct Entry {
    LogLevel level;
    std::string message;
  };
  ScopedLogCapture();
  ~ScopedLogCapture();
  ScopedLogCapture(const ScopedLogCapture&) = delete;
  ScopedLogCapture& operator=(const ScopedLogCapture&) = delete;

  const std::vector<Entry>& entries() const { return entries_; }
  // Number of captured warnings whose text contains `needle`.
  int count_warnings(std::string_view needle) const;

private:
  friend void log_message(LogLevel level, std::string_view message);
  std::vector<Entry> entries_;
  ScopedLogCapture* previous_;
  LogLevel previous_level_;
};

}  // namespace glint
