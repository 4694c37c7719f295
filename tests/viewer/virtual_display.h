#pragma once
// An X server of its own for the viewer's tests: Xvfb (Mesa's llvmpipe draws the GL 4.5 context;
// NVIDIA's GLX where that is Xvfb's GL) on a free display number Xvfb picks itself (-displayfd), so
// tests running side by side do not collide, and DISPLAY set to it while the object lives. Tests
// skip themselves when Xvfb is not installed.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace glint::testing {

class VirtualDisplay {
public:
  VirtualDisplay() {
    const char* candidates[] = {"/usr/bin/Xvfb", "/usr/local/bin/Xvfb"};
    for (const char* candidate : candidates)
      if (std::filesystem::exists(candidate)) xvfb_ = candidate;
    if (xvfb_.empty()) return;
    int fds[2];
    if (::pipe(fds) != 0) return;
    server_ = ::fork();
    if (server_ == 0) {
      ::close(fds[0]);
      const std::string fd = std::to_string(fds[1]);
      if (std::freopen("/dev/null", "w", stderr) == nullptr) ::_exit(126);  // Xvfb's start-up chatter
      ::execl(xvfb_.c_str(), xvfb_.c_str(), "-displayfd", fd.c_str(), "-screen", "0", "1920x1080x24", "-nolisten",
              "tcp", static_cast<char*>(nullptr));
      ::_exit(127);
    }
    ::close(fds[1]);
    // Xvfb writes the display number once it accepts connections.
    std::string number;
    char c = 0;
    while (::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (number.empty()) return;
    display_ = ":" + number;
    if (const char* old = std::getenv("DISPLAY")) old_display_ = old;
    ::setenv("DISPLAY", display_.c_str(), 1);
  }
  ~VirtualDisplay() {
    if (old_display_) ::setenv("DISPLAY", old_display_->c_str(), 1);
    else ::unsetenv("DISPLAY");
    if (server_ > 0) {
      ::kill(server_, SIGTERM);
      ::waitpid(server_, nullptr, 0);
    }
  }
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;

  bool ready() const { return !display_.empty(); }
  const std::string& display() const { return display_; }  // ":N"

private:
  std::string xvfb_;
  pid_t server_ = -1;
  std::string display_;
  std::optional<std::string> old_display_;
};

// Skips the test when no virtual display could be started.
#define GLINT_REQUIRE_DISPLAY(display) \
  if (!(display).ready()) GTEST_SKIP() << "Xvfb is not installed or did not start: the viewer needs a display"

}  // namespace glint::testing
