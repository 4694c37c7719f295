#include "app/video_writer.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

extern char** environ;

namespace glint {
namespace {

// The ffmpeg muxer for the target's extension. The temporary name does not end in the extension, so
// ffmpeg cannot guess the container and is told with -f.
std::string container_for(const std::filesystem::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".mp4" || extension == ".m4v") return "mp4";
  if (extension == ".mov") return "mov";
  if (extension == ".mkv") return "matroska";
  fail("cannot write video '{}': use a .mp4, .mov or .mkv file name", path.string());
}

// Writes to ffmpeg's stdin without SIGPIPE. If ffmpeg has exited, write() raises SIGPIPE, whose default
// action would kill glint without a word; with the signal blocked for the write, write() fails with
// EPIPE instead and the pending signal is consumed before it is unblocked. This keeps the process's
// signal handling untouched (a library must not install handlers behind the program's back).
class SigpipeBlockedScope {
public:
  SigpipeBlockedScope() {
    sigemptyset(&sigpipe_);
    sigaddset(&sigpipe_, SIGPIPE);
    sigset_t pending;
    sigpending(&pending);
    was_pending_ = sigismember(&pending, SIGPIPE) == 1;
    pthread_sigmask(SIG_BLOCK, &sigpipe_, &previous_);
  }
  ~SigpipeBlockedScope() {
    if (raised_ && !was_pending_) {
      const timespec no_wait{0, 0};
      while (sigtimedwait(&sigpipe_, nullptr, &no_wait) < 0 && errno == EINTR) {
      }
    }
    pthread_sigmask(SIG_SETMASK, &previous_, nullptr);
  }
  SigpipeBlockedScope(const SigpipeBlockedScope&) = delete;
  SigpipeBlockedScope& operator=(const SigpipeBlockedScope&) = delete;
  void note_epipe() { raised_ = true; }

private:
  sigset_t sigpipe_{};
  sigset_t previous_{};
  bool was_pending_ = false;
  bool raised_ = false;
};

// Returns 0 or the errno of the failed write.
int write_all(int fd, const unsigned char* data, std::size_t size) {
  SigpipeBlockedScope sigpipe;
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      const int write_errno = errno;
      if (write_errno == EPIPE) sigpipe.note_epipe();
      return write_errno;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return 0;
}

// The last few lines ffmpeg printed, joined into one line for a one-line error message.
std::string tail_of_log(int fd) {
  if (fd < 0) return {};
  struct stat info {};
  if (::fstat(fd, &info) != 0) return {};
  const off_t size = info.st_size;
  const off_t start = std::max<off_t>(0, size - 4096);
  std::string text(static_cast<std::size_t>(size - start), '\0');
  const ssize_t got = ::pread(fd, text.data(), text.size(), start);
  text.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  std::vector<std::string> lines;
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find_first_of("\r\n", begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    const std::size_t first = line.find_first_not_of(" \t");
    if (first != std::string::npos) lines.push_back(line.substr(first));
    begin = end + 1;
  }
  const std::size_t keep = std::min<std::size_t>(lines.size(), 3);
  std::string tail;
  for (std::size_t i = lines.size() - keep; i < lines.size(); ++i) {
    if (!tail.empty()) tail += " | ";
    tail += lines[i];
  }
  return tail.empty() ? std::string("(ffmpeg printed nothing)") : tail;
}

std::string describe_wait_status(int status) {
  if (WIFEXITED(status)) return fmt::format("exit status {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return fmt::format("killed by signal {}", WTERMSIG(status));
  return fmt::format("wait status {}", status);
}

// An unlinked temporary file for ffmpeg's stderr: a file rather than a pipe, so that ffmpeg never
// blocks on a full pipe that nobody reads while glint is busy rendering.
int open_log_file() {
  std::string name = (std::filesystem::temp_directory_path() / "glint-ffmpeg-XXXXXX").string();
  const int fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) fail("--video: cannot create a temporary file for ffmpeg's messages: {}", std::strerror(errno));
  ::unlink(name.c_str());
  return fd;
}

// posix_spawn's setup objects, destroyed on every path out.
struct SpawnSetup {
  posix_spawn_file_actions_t actions{};
  posix_spawnattr_t attributes{};
  SpawnSetup() {
    posix_spawn_file_actions_init(&actions);
    posix_spawnattr_init(&attributes);
  }
  ~SpawnSetup() {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
  }
  SpawnSetup(const SpawnSetup&) = delete;
  SpawnSetup& operator=(const SpawnSetup&) = delete;
};

}  // namespace

std::optional<std::filesystem::path> find_program_on_path(std::string_view program) {
  const char* path_variable = std::getenv("PATH");
  if (path_variable == nullptr || program.empty()) return std::nullopt;
  std::string_view folders(path_variable);
  while (true) {
    const std::size_t colon = folders.find(':');
    const std::string_view folder = folders.substr(0, colon);
    // An empty entry means the current folder (POSIX); it is honoured like a shell would.
    const std::filesystem::path candidate = std::filesystem::path(folder.empty() ? "." : folder) / program;
    std::error_code error;
    if (std::filesystem::is_regular_file(candidate, error) && ::access(candidate.c_str(), X_OK) == 0)
      return candidate;
    if (colon == std::string_view::npos) return std::nullopt;
    folders.remove_prefix(colon + 1);
  }
}

FfmpegVideoWriter::FfmpegVideoWriter(std::filesystem::path path, int width, int height, double fps)
    : path_(std::move(path)), width_(width), height_(height) {
  if (width <= 0 || height <= 0) fail("cannot write video '{}': frame size {}x{} is not positive", path_.string(), width, height);
  if (!std::isfinite(fps) || fps <= 0.0) fail("cannot write video '{}': frame rate {} is not positive", path_.string(), fps);
  const std::string container = container_for(path_);
  const std::filesystem::path folder = path_.parent_path().empty() ? std::filesystem::path(".") : path_.parent_path();
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error))
    fail("cannot write video '{}': folder '{}' does not exist", path_.string(), folder.string());
  const std::optional<std::filesystem::path> ffmpeg = find_program_on_path("ffmpeg");
  if (!ffmpeg) fail("--video needs ffmpeg on PATH (to write '{}')", path_.string());

  temporary_ = temporary_sibling_path(path_);
  const std::vector<std::string> arguments = {
      ffmpeg->string(), "-hide_banner", "-loglevel", "error", "-nostats", "-y",
      // Input: raw RGBA frames on stdin, top row first (as ImageRgba8 stores them).
      "-f", "rawvideo", "-pix_fmt", "rgba", "-video_size", fmt::format("{}x{}", width, height),
      "-framerate", fmt::format("{}", fps), "-i", "pipe:0",
      // Output: H.264 in yuv420p, whose 2x2 chroma blocks need even sizes.
      "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-preset", "medium", "-crf", "18",
      "-pix_fmt", "yuv420p", "-f", container, temporary_.string()};
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);

  log_fd_ = open_log_file();
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    const int pipe_errno = errno;
    ::close(log_fd_);
    fail("--video: cannot create a pipe to ffmpeg: {}", std::strerror(pipe_errno));
  }
  const int read_end = fds[0];
  pipe_fd_ = fds[1];

  SpawnSetup setup;
  // Both descriptors are close-on-exec; dup2 onto 0 and 2 gives the child its own inheritable copies.
  posix_spawn_file_actions_adddup2(&setup.actions, read_end, 0);
  posix_spawn_file_actions_addopen(&setup.actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&setup.actions, log_fd_, 2);
  // ffmpeg starts with no blocked signals and default SIGPIPE, whatever this thread does.
  sigset_t signals;
  sigemptyset(&signals);
  posix_spawnattr_setsigmask(&setup.attributes, &signals);
  sigaddset(&signals, SIGPIPE);
  posix_spawnattr_setsigdefault(&setup.attributes, &signals);
  posix_spawnattr_setflags(&setup.attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

  const int spawn_error = ::posix_spawn(&pid_, ffmpeg->c_str(), &setup.actions, &setup.attributes, argv.data(), environ);
  ::close(read_end);
  if (spawn_error != 0) {
    pid_ = -1;
    ::close(pipe_fd_);
    ::close(log_fd_);
    pipe_fd_ = log_fd_ = -1;
    fail("--video: cannot start '{}': {}", ffmpeg->string(), std::strerror(spawn_error));
  }
}

FfmpegVideoWriter::~FfmpegVideoWriter() {
  if (!finished_) abandon();
  if (log_fd_ >= 0) ::close(log_fd_);
}

void FfmpegVideoWriter::add_frame(const ImageRgba8& frame) {
  if (finished_ || pipe_fd_ < 0) fail("cannot write video '{}': the writer is closed", path_.string());
  if (frame.width != width_ || frame.height != height_ ||
      frame.pixels.size() != static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_))
    fail("cannot write video '{}': frame {} is {}x{}, the video is {}x{}", path_.string(), frames_, frame.width,
         frame.height, width_, height_);
  const int error = write_all(pipe_fd_, reinterpret_cast<const unsigned char*>(frame.pixels.data()),
                              frame.pixels.size() * sizeof(glm::u8vec4));
  if (error == EPIPE) fail_with_ffmpeg_output(fmt::format("ffmpeg stopped at frame {}", frames_));
  if (error != 0) {
    abandon();
    fail("cannot write video '{}': writing to ffmpeg failed: {}", path_.string(), std::strerror(error));
  }
  ++frames_;
}

void FfmpegVideoWriter::finish() {
  if (finished_ || pipe_fd_ < 0) fail("cannot write video '{}': the writer is closed", path_.string());
  if (frames_ == 0) {
    abandon();
    fail("cannot write video '{}': no frames were added", path_.string());
  }
  ::close(pipe_fd_);  // end of input: ffmpeg flushes the encoder and writes the file's index
  pipe_fd_ = -1;
  const int status = wait_for_ffmpeg();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    ::unlink(temporary_.c_str());
    fail("cannot write video '{}': ffmpeg failed ({}): {}", path_.string(), describe_wait_status(status),
         tail_of_log(log_fd_));
  }
  finished_ = true;
  rename_onto(temporary_, path_);
}

void FfmpegVideoWriter::fail_with_ffmpeg_output(std::string_view what) {
  if (pipe_fd_ >= 0) ::close(pipe_fd_);
  pipe_fd_ = -1;
  const int status = wait_for_ffmpeg();
  ::unlink(temporary_.c_str());
  fail("cannot write video '{}': {} ({}): {}", path_.string(), what, describe_wait_status(status),
       tail_of_log(log_fd_));
}

int FfmpegVideoWriter::wait_for_ffmpeg() {
  int status = 0;
  if (pid_ <= 0) return status;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  return status;
}

void FfmpegVideoWriter::abandon() {
  if (pipe_fd_ >= 0) ::close(pipe_fd_);
  pipe_fd_ = -1;
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    wait_for_ffmpeg();
  }
  // After ffmpeg is gone, so that it cannot create the file again behind our back.
  ::unlink(temporary_.c_str());
}

}  // namespace glint
