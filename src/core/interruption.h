#pragma once
// Ctrl-C (SIGINT) and SIGTERM during a long run. While an InterruptionScope is alive, the first such
// signal only sets a flag: the run checks it between pieces of work (a frame, a benchmark cell),
// finishes the file it is writing, commits what it has (timings.csv rows, run.json marked
// "interrupted") and exits with 128 + the signal's number, as a shell reports a process killed by
// it. Without the scope the default action would kill the process mid-write and leave temporaries
// behind. The handler is installed with SA_RESETHAND, so a second signal kills at once, as users
// expect of a second Ctrl-C.
//
//   InterruptionScope interruptible;
//   for (int frame : frames) { if (interruption_requested()) break; render(frame); }
//   if (interruption_requested()) return interrupted_exit_code();
#include "core/error.h"

#include <memory>

namespace glint {

class InterruptionScope {
public:
  InterruptionScope();   // installs the handlers and clears any earlier request
  ~InterruptionScope();  // restores the previous handlers
  InterruptionScope(const InterruptionScope&) = delete;
  InterruptionScope& operator=(const InterruptionScope&) = delete;

private:
  struct Saved;
  std::unique_ptr<Saved> saved_;
};

// Whether SIGINT or SIGTERM arrived while a scope was alive.
bool interruption_requested();
// The signal that arrived (SIGINT or SIGTERM), 0 if none.
int interruption_signal();
// 128 + interruption_signal() (130 for SIGINT, 143 for SIGTERM); 1 if none arrived.
int interrupted_exit_code();
// "SIGINT", "SIGTERM" or "no signal".
const char* interruption_signal_name();

// Thrown by code that cannot return early on its own (deep inside a benchmark cell); the CLI prints
// its message as one line and exits with interrupted_exit_code().
class Interrupted : public Error {
public:
  using Error::Error;
};

// Throws Interrupted("<what>: interrupted by SIGINT") when a signal arrived.
void throw_if_interrupted(const char* what);

}  // namespace glint
