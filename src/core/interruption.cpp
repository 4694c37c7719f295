#include "core/interruption.h"

#include <fmt/format.h>

#include <atomic>
#include <csignal>
#include <unistd.h>

namespace glint {
namespace {

// Lock-free, so the handler may store to it (async-signal-safe).
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void note_interruption(int signal) {
  g_signal.store(signal, std::memory_order_relaxed);
  // write(2) is async-signal-safe; fmt and stdio are not.
  constexpr char kMessage[] =
      "\nglint: interrupted; finishing the current file and writing what was done (again to stop at once)\n";
  [[maybe_unused]] const ssize_t written = ::write(STDERR_FILENO, kMessage, sizeof(kMessage) - 1);
}

constexpr int kSignals[] = {SIGINT, SIGTERM};

}  // namespace

struct InterruptionScope::Saved {
  struct sigaction previous[2];
};

InterruptionScope::InterruptionScope() : saved_(std::make_unique<Saved>()) {
  g_signal.store(0, std::memory_order_relaxed);
  struct sigaction action {};
  action.sa_handler = note_interruption;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND;  // the second signal takes the default action: the process ends
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &action, &saved_->previous[i]);
}

InterruptionScope::~InterruptionScope() {
  for (int i = 0; i < 2; ++i) sigaction(kSignals[i], &saved_->previous[i], nullptr);
}

bool interruption_requested() { return g_signal.load(std::memory_order_relaxed) != 0; }

int interruption_signal() { return g_signal.load(std::memory_order_relaxed); }

int interrupted_exit_code() {
  const int signal = interruption_signal();
  return signal == 0 ? 1 : 128 + signal;
}

const char* interruption_signal_name() {
  switch (interruption_signal()) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    default: return "no signal";
  }
}

void throw_if_interrupted(const char* what) {
  if (interruption_requested()) throw Interrupted(fmt::format("{}: interrupted by {}", what, interruption_signal_name()));
}

}  // namespace glint
