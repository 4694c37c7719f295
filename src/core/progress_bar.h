#pragma once
// Progress of a long loop (frames rendered, benchmark cases run) on stderr.
//
// On a terminal one line is redrawn in place with '\r' (label, bar, done/total, percent, items/s,
// ETA, elapsed), at most about 10 times a second so that printing never costs more than the work.
// When stderr is a file or a pipe (CI logs, `2> log.txt`), '\r' redraws would pile up as garbage, so a
// plain full line is printed every 10 seconds instead. finish() prints one final line with the totals
// and the mean rate in both styles.
//
// Rate and ETA use the mean rate since the bar was created: the frames of a walkthrough cost about the
// same, and the mean does not jump around like a per-frame rate.
#include <chrono>
#include <cstddef>
#include <functional>
#include <mutex>
#include <optional>
#include <ostream>
#include <string>

namespace glint {

enum class ProgressStyle { terminal, plain };

using ProgressClock = std::function<std::chrono::steady_clock::time_point()>;

// Where and how a ProgressBar prints. Tests inject a stream and a fake clock.
struct ProgressOutput {
  ProgressStyle style = ProgressStyle::plain;
  std::ostream* stream = nullptr;  // not owned; nullptr means std::cerr
  ProgressClock clock;             // empty means std::chrono::steady_clock::now
  std::chrono::duration<double> plain_interval = std::chrono::seconds(10);
  std::chrono::duration<double> terminal_redraw_interval = std::chrono::milliseconds(100);

  // std::cerr, terminal style when stderr is a terminal (isatty), plain otherwise.
  static ProgressOutput for_stderr();
};

// What a bar knows at one moment; rate and ETA are empty until they can be computed (nothing done
// yet, or no time elapsed).
struct ProgressSnapshot {
  std::size_t done = 0;
  std::size_t total = 0;
  double elapsed_seconds = 0.0;
  std::optional<double> items_per_second;
  std::optional<double> eta_seconds;  // 0 once done >= total
};

// "0:07", "12:34", "1:02:03" (seconds rounded to the nearest whole one; negative counts as 0).
std::string format_duration(double seconds);

class ProgressBar {
public:
  // A terminal bar draws its empty line at once, so a slow first item does not look like a hang.
  ProgressBar(std::string label, std::size_t total, ProgressOutput output = ProgressOutput::for_stderr());
  // A terminal bar that was not finished ends its line, so whatever is printed next (an error message)
  // starts on a line of its own.
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  // Counts `count` more items done and prints if it is time to. Safe to call from several threads.
  void tick(std::size_t count = 1);
  // Prints the final line (totals, elapsed, mean rate). Only the first call prints; later ticks still
  // count but print nothing.
  void finish();

  ProgressSnapshot snapshot() const;

private:
  using TimePoint = std::chrono::steady_clock::time_point;
  ProgressSnapshot snapshot_at(TimePoint now) const;
  std::string status_text(const ProgressSnapshot& snapshot) const;
  void draw_terminal_line(const std::string& line, bool end_line);

  std::string label_;
  std::size_t total_;
  ProgressOutput output_;
  std::ostream& stream_;
  TimePoint start_;
  TimePoint last_print_;
  std::size_t done_ = 0;
  std::size_t drawn_width_ = 0;  // terminal: length of the line on screen, to blank its leftovers
  bool line_open_ = false;       // terminal: a line was drawn and not ended with '\n'
  bool finished_ = false;
  mutable std::mutex mutex_;
};

}  // namespace glint
