#include "core/progress_bar.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace glint {
namespace {

constexpr std::size_t kBarWidth = 24;

// Three significant digits or so, without exponents: "0.123", "4.56", "78.9", "1234".
std::string format_rate(const std::optional<double>& rate) {
  if (!rate) return "--";
  const double r = *rate;
  if (r < 1.0) return fmt::format("{:.3f}", r);
  if (r < 10.0) return fmt::format("{:.2f}", r);
  if (r < 100.0) return fmt::format("{:.1f}", r);
  return fmt::format("{:.0f}", r);
}

std::string format_optional_duration(const std::optional<double>& seconds) {
  return seconds ? format_duration(*seconds) : std::string("--");
}

// A total of 0 counts as complete, so the bar never divides by zero.
double fraction_done(const ProgressSnapshot& s) {
  if (s.total == 0) return 1.0;
  return std::min(1.0, static_cast<double>(s.done) / static_cast<double>(s.total));
}

}  // namespace

ProgressOutput ProgressOutput::for_stderr() {
  ProgressOutput output;
  output.style = ::isatty(STDERR_FILENO) == 1 ? ProgressStyle::terminal : ProgressStyle::plain;
  output.stream = &std::cerr;
  return output;
}

std::string format_duration(double seconds) {
  const long long whole = std::isfinite(seconds) ? std::max(0LL, std::llround(seconds)) : 0LL;
  const long long hours = whole / 3600, minutes = whole / 60 % 60, secs = whole % 60;
  if (hours > 0) return fmt::format("{}:{:02}:{:02}", hours, minutes, secs);
  return fmt::format("{}:{:02}", minutes, secs);
}

ProgressBar::ProgressBar(std::string label, std::size_t total, ProgressOutput output)
    : label_(std::move(label)), total_(total), output_(std::move(output)),
      stream_(output_.stream != nullptr ? *output_.stream : std::cerr) {
  if (!output_.clock) output_.clock = [] { return std::chrono::steady_clock::now(); };
  start_ = last_print_ = output_.clock();
  if (output_.style == ProgressStyle::terminal) draw_terminal_line(status_text(snapshot_at(start_)), false);
}

ProgressBar::~ProgressBar() {
  std::lock_guard lock(mutex_);
  if (line_open_) {
    stream_ << '\n';
    stream_.flush();
  }
}

void ProgressBar::tick(std::size_t count) {
  std::lock_guard lock(mutex_);
  done_ += count;
  if (finished_) return;
  const TimePoint now = output_.clock();
  const auto since_print = now - last_print_;
  if (output_.style == ProgressStyle::terminal) {
    if (since_print < output_.terminal_redraw_interval) return;
    last_print_ = now;
    draw_terminal_line(status_text(snapshot_at(now)), false);
  } else {
    if (since_print < output_.plain_interval) return;
    last_print_ = now;
    stream_ << status_text(snapshot_at(now)) << '\n';
    stream_.flush();
  }
}

void ProgressBar::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  const ProgressSnapshot s = snapshot_at(output_.clock());
  std::string line = fmt::format("{}: {}/{} done in {}, {} items/s mean", label_, s.done, s.total,
                                 format_duration(s.elapsed_seconds), format_rate(s.items_per_second));
  if (output_.style == ProgressStyle::terminal) {
    draw_terminal_line(line, true);
  } else {
    stream_ << line << '\n';
    stream_.flush();
  }
}

ProgressSnapshot ProgressBar::snapshot() const {
  std::lock_guard lock(mutex_);
  return snapshot_at(output_.clock());
}

ProgressSnapshot ProgressBar::snapshot_at(TimePoint now) const {
  ProgressSnapshot s;
  s.done = done_;
  s.total = total_;
  s.elapsed_seconds = std::max(0.0, std::chrono::duration<double>(now - start_).count());
  if (s.done > 0 && s.elapsed_seconds > 0.0) s.items_per_second = static_cast<double>(s.done) / s.elapsed_seconds;
  if (s.done >= s.total) s.eta_seconds = 0.0;
  else if (s.items_per_second) s.eta_seconds = static_cast<double>(s.total - s.done) / *s.items_per_second;
  return s;
}

std::string ProgressBar::status_text(const ProgressSnapshot& s) const {
  const double fraction = fraction_done(s);
  const int percent = static_cast<int>(std::floor(fraction * 100.0));
  const std::string counts = fmt::format("{}/{} ({}%), {} items/s, ETA {}, elapsed {}", s.done, s.total, percent,
                                         format_rate(s.items_per_second), format_optional_duration(s.eta_seconds),
                                         format_duration(s.elapsed_seconds));
  if (output_.style == ProgressStyle::plain) return fmt::format("{}: {}", label_, counts);
  const auto filled = static_cast<std::size_t>(std::floor(fraction * static_cast<double>(kBarWidth)));
  std::string bar(filled, '#');
  bar.append(kBarWidth - filled, '.');
  return fmt::format("{} [{}] {}", label_, bar, counts);
}

void ProgressBar::draw_terminal_line(const std::string& line, bool end_line) {
  // Blank what is left of a longer previous line (the ETA can shrink from "1:02:03" to "59:59").
  const std::size_t padding = drawn_width_ > line.size() ? drawn_width_ - line.size() : 0;
  stream_ << '\r' << line << std::string(padding, ' ');
  drawn_width_ = line.size();
  if (end_line) stream_ << '\n';
  line_open_ = !end_line;
  stream_.flush();
}

}  // namespace glint
