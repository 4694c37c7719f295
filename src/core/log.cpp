#include "core/log.h"

#include <cstdio>
#include <mutex>

namespace glint {
namespace {

LogLevel g_level = LogLevel::warning;
ScopedLogCapture* g_capture = nullptr;
std::mutex g_mutex;

const char* prefix(LogLevel level) {
  switch (level) {
    case LogLevel::debug: return "glint: debug: ";
    case LogLevel::info: return "glint: ";
    case LogLevel::warning: return "glint: warning: ";
    case LogLevel::error: return "glint: error: ";
  }
  return "glint: ";
}

}  // namespace

void set_log_level(LogLevel minimum) { g_level = minimum; }
LogLevel log_level() { return g_level; }

void log_message(LogLevel level, std::string_view message) {
  std::lock_guard lock(g_mutex);
  if (g_capture != nullptr) {
    g_capture->entries_.push_back({level, std::string(message)});
    return;
  }
  if (level < g_level) return;
  std::fprintf(stderr, "%s%.*s\n", prefix(level), static_cast<int>(message.size()), message.data());
}

ScopedLogCapture::ScopedLogCapture() : previous_(g_capture), previous_level_(g_level) {
  std::lock_guard lock(g_mutex);
  g_capture = this;
  g_level = LogLevel::debug;
}

ScopedLogCapture::~ScopedLogCapture() {
  std::lock_guard lock(g_mutex);
  g_capture = previous_;
  g_level = previous_level_;
}

int ScopedLogCapture::count_warnings(std::string_view needle) const {
  int count = 0;
  for (const auto& entry : entries_)
    if (entry.level == LogLevel::warning && entry.message.find(needle) != std::string::npos) ++count;
  return count;
}

}  // namespace glint
