#include "core/atomic_file.h"

#include "core/error.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <streambuf>
#include <string>
#include <vector>

namespace glint {
namespace {

// A stream buffer over a POSIX file descriptor. It exists (instead of std::ofstream) to keep the errno
// of a failed write: "No space left on device" is what a user needs to read, not "stream error".
class FdStreamBuffer : public std::streambuf {
public:
  explicit FdStreamBuffer(int fd) : fd_(fd), buffer_(64 * 1024) { reset_put_area(); }

  // errno of the first failed write, or 0. After a failure every further write fails too, so a file
  // with a hole in the middle can never be committed.
  int error() const { return error_; }

  // Called when the descriptor is closed: later writes through the stream fail (badbit) instead of
  // going to whatever file reuses the descriptor's number.
  void descriptor_closed() {
    fd_ = -1;
    if (error_ == 0) error_ = EBADF;
  }

protected:
  int_type overflow(int_type ch) override {
    if (!drain()) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }

  std::streamsize xsputn(const char* data, std::streamsize count) override {
    const auto size = static_cast<std::size_t>(count);
    if (size > static_cast<std::size_t>(epptr() - pptr())) {
      if (!drain()) return 0;
      // Large blocks (a whole PNG, a video frame) skip the copy into the buffer.
      if (size >= buffer_.size()) return write_all(data, size) ? count : 0;
    }
    std::memcpy(pptr(), data, size);
    pbump(static_cast<int>(size));
    return count;
  }

  int sync() override { return drain() ? 0 : -1; }

private:
  void reset_put_area() { setp(buffer_.data(), buffer_.data() + buffer_.size()); }

  bool drain() {
    const bool written = write_all(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    reset_put_area();
    return written;
  }

  bool write_all(const char* data, std::size_t size) {
    if (error_ != 0) return false;
    while (size > 0) {
      const ssize_t written = ::write(fd_, data, size);
      if (written < 0) {
        if (errno == EINTR) continue;
        error_ = errno;
        return false;
      }
      data += written;
      size -= static_cast<std::size_t>(written);
    }
    return true;
  }

  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

std::filesystem::path folder_of(const std::filesystem::path& path) {
  return path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
}

}  // namespace

std::filesystem::path temporary_sibling_path(const std::filesystem::path& path) {
  static std::atomic<unsigned> counter{0};
  std::string name = ".";
  name += path.filename().string();
  name += ".tmp-";
  name += std::to_string(::getpid());
  name += '-';
  name += std::to_string(counter++);
  return path.parent_path() / name;
}

namespace {

// The process id in a temporary's name ".<name>.tmp-<pid>-<n>", or 0 when `name` is not one.
pid_t temporary_owner(const std::string& name) {
  const std::size_t tmp = name.rfind(".tmp-");
  if (name.empty() || name.front() != '.' || tmp == std::string::npos || tmp == 0) return 0;
  const std::size_t dash = name.find('-', tmp + 5);
  if (dash == std::string::npos || dash == tmp + 5 || dash + 1 == name.size()) return 0;
  const std::string pid_text = name.substr(tmp + 5, dash - tmp - 5);
  const std::string counter_text = name.substr(dash + 1);
  const auto all_digits = [](const std::string& text) {
    return std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  };
  if (!all_digits(pid_text) || !all_digits(counter_text) || pid_text.size() > 9) return 0;
  return static_cast<pid_t>(std::stol(pid_text));
}

bool process_is_running(pid_t pid) { return ::kill(pid, 0) == 0 || errno == EPERM; }

}  // namespace

std::size_t remove_stale_temporaries(const std::filesystem::path& folder) {
  std::size_t removed = 0;
  std::error_code error;
  for (std::filesystem::recursive_directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (!it->is_regular_file(error)) continue;
    const pid_t owner = temporary_owner(it->path().filename().string());
    if (owner <= 0 || owner == ::getpid() || process_is_running(owner)) continue;
    std::error_code ignored;
    removed += std::filesystem::remove(it->path(), ignored) ? 1 : 0;
  }
  return removed;
}

void rename_onto(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    ::unlink(temporary.c_str());
    fail("cannot write '{}': {}", path.string(), std::strerror(rename_errno));
  }
}

struct AtomicFileWriter::State {
  State(std::filesystem::path final_path, std::filesystem::path temporary_file, int descriptor)
      : path(std::move(final_path)), temporary(std::move(temporary_file)), fd(descriptor), buffer(fd),
        stream(&buffer) {}

  std::filesystem::path path;
  std::filesystem::path temporary;
  int fd;  // -1 once closed
  FdStreamBuffer buffer;
  std::ostream stream;
  bool committed = false;
};

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path) {
  if (path.empty() || !path.has_filename()) fail("cannot write '{}': not a file name", path.string());
  std::filesystem::path temporary = temporary_sibling_path(path);
  // O_EXCL: never write into a file someone else created under the same name. 0666 (less the umask)
  // gives the final file the permissions any ordinarily created file would have.
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) {
    const int open_errno = errno;
    if (open_errno == ENOENT) fail("cannot write '{}': folder '{}' does not exist", path.string(), folder_of(path).string());
    if (open_errno == ENOTDIR) fail("cannot write '{}': '{}' is not a folder", path.string(), folder_of(path).string());
    fail("cannot write '{}': {}", path.string(), std::strerror(open_errno));
  }
  state_ = std::make_unique<State>(std::move(path), std::move(temporary), fd);
}

AtomicFileWriter::~AtomicFileWriter() {
  if (!state_) return;  // moved from
  if (state_->fd >= 0) ::close(state_->fd);
  if (!state_->committed) ::unlink(state_->temporary.c_str());
}

AtomicFileWriter::AtomicFileWriter(AtomicFileWriter&&) noexcept = default;

AtomicFileWriter& AtomicFileWriter::operator=(AtomicFileWriter&& other) noexcept {
  if (this != &other) {
    AtomicFileWriter discarded(std::move(*this));  // the old file (if any) is abandoned like in the destructor
    state_ = std::move(other.state_);
  }
  return *this;
}

std::ostream& AtomicFileWriter::stream() { return state_->stream; }

void AtomicFileWriter::write(std::string_view bytes) { write(bytes.data(), bytes.size()); }

void AtomicFileWriter::write(const void* data, std::size_t size) {
  if (state_->committed || state_->fd < 0) fail("cannot write '{}': the writer is closed (committed or failed)", state_->path.string());
  state_->stream.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!state_->stream) {
    const int error = state_->buffer.error();
    fail("cannot write '{}': {}", state_->path.string(), error != 0 ? std::strerror(error) : "the output stream failed");
  }
}

void AtomicFileWriter::commit() {
  State& state = *state_;
  if (state.committed || state.fd < 0) fail("cannot write '{}': the writer is closed (committed or failed)", state.path.string());
  state.stream.flush();
  int error = state.buffer.error();
  const bool stream_failed = !state.stream;
  // close() is where some file systems (NFS) report a failed write.
  if (::close(state.fd) != 0 && error == 0) error = errno;
  state.fd = -1;
  state.buffer.descriptor_closed();
  if (error != 0 || stream_failed) {
    ::unlink(state.temporary.c_str());
    fail("cannot write '{}': {}", state.path.string(), error != 0 ? std::strerror(error) : "the output stream failed");
  }
  rename_onto(state.temporary, state.path);
  state.committed = true;
}

const std::filesystem::path& AtomicFileWriter::path() const { return state_->path; }
const std::filesystem::path& AtomicFileWriter::temporary_path() const { return state_->temporary; }
bool AtomicFileWriter::committed() const { return state_->committed; }

void write_file_atomically(const std::filesystem::path& path, std::string_view bytes) {
  AtomicFileWriter writer(path);
  writer.write(bytes);
  writer.commit();
}

}  // namespace glint
