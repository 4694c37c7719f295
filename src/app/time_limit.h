#pragma once
// `glint bench --time-limit`: a run that must end before a deadline (a Slurm job's --time, a
// machine lent for ten minutes) starts no cell, and under mpirun no piece, once the limit has passed
// since the command started; what is under way finishes and is kept, and the command exits with
// kTimeLimitExitCode so a job script can tell "run me again" from success and from failure. The same
// command then resumes the run (app/bench/resume.h). Unlike a SIGTERM at the deadline, no work under
// way is lost.
#include "core/error.h"

#include <chrono>
#include <optional>
#include <string>

namespace glint {

// EX_TEMPFAIL of sysexits.h: a temporary failure, to be retried.
inline constexpr int kTimeLimitExitCode = 75;

// Thrown when the limit stopped a run before it was done; the CLI prints its message as one line and
// exits with kTimeLimitExitCode.
class TimeLimitReached : public Error {
public:
  using Error::Error;
};

// "90" or "90s" (seconds), "50m" (minutes), "7h" (hours), "1.5h": seconds >= 0. glint::Error naming
// `flag` for anything else.
double parse_time_limit_seconds(const std::string& flag, const std::string& text);

class TimeLimit {
public:
  TimeLimit() = default;  // none: nothing ever passes
  TimeLimit(std::string text, double seconds, std::chrono::steady_clock::time_point start);
  // From the flag's value (empty: none), counted from `start`.
  static TimeLimit from_flag(const std::string& flag, const std::string& text,
                             std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now());

  bool passed() const { return until_ && std::chrono::steady_clock::now() >= *until_; }
  const std::optional<std::chrono::steady_clock::time_point>& until() const { return until_; }
  const std::string& text() const { return text_; }  // as given, for messages

private:
  std::string text_;
  std::optional<std::chrono::steady_clock::time_point> until_;
};

}  // namespace glint
