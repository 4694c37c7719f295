#pragma once
// Files that appear whole or not at all. Every output glint writes (PNG frames, CSV tables, videos)
// goes to a temporary name in the target's own folder and is renamed onto the final path only when
// complete, so a crash, an error or Ctrl-C never leaves a half-written file under the final name and a
// reader never sees one. rename(2) within one folder (one file system) is atomic.
//
// This protects against the process dying, not against power loss: there is no fsync, because an
// fsync per rendered frame would cost more than the frame on some file systems.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string_view>

namespace glint {

// `<folder>/.<name>.tmp-<pid>-<n>` next to `path`: hidden (so folder listings and globs such as
// frame_*.png skip it), unique among threads and processes writing at the same time, and in the same
// folder as `path`, so renaming it onto `path` is atomic.
std::filesystem::path temporary_sibling_path(const std::filesystem::path& path);

// Removes the temporaries (see temporary_sibling_path) under `folder` and its subfolders that a process
// no longer running left behind: a run killed without a chance to clean up (SIGKILL, a power cut).
// Temporaries of running processes, this one included, are kept. Returns how many were removed.
std::size_t remove_stale_temporaries(const std::filesystem::path& folder);

// Renames a finished temporary onto `path` (replacing an existing file). On failure the temporary is
// removed and a glint::Error names `path` and the reason.
void rename_onto(const std::filesystem::path& temporary, const std::filesystem::path& path);

// Writes one file through a temporary sibling (see temporary_sibling_path). Bytes go through stream()
// or write(); commit() makes them visible under the final path. Destroying a writer that was not
// committed (an exception unwinding, an early return) removes the temporary, leaving any existing file
// at the final path untouched.
//
// Data is buffered (64 KiB) and written to the temporary as it comes, so a long run does not hold its
// whole output in memory. Errors (missing folder, full disk, rename failure) are glint::Errors naming
// the final path and strerror.
class AtomicFileWriter {
public:
  // Creates the temporary. A missing folder, a folder that is a file, or no permission is an error.
  explicit AtomicFileWriter(std::filesystem::path path);
  ~AtomicFileWriter();
  AtomicFileWriter(AtomicFileWriter&&) noexcept;
  AtomicFileWriter& operator=(AtomicFileWriter&&) noexcept;
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  // For formatted output. A failed write sets the stream's badbit; commit() then reports the error.
  std::ostream& stream();
  // Appends raw bytes; throws at once if the data cannot be written.
  void write(std::string_view bytes);
  void write(const void* data, std::size_t size);

  // Flushes, checks that everything was written, closes and renames onto the final path. Throws on
  // any failure (and removes the temporary). Calling it twice, or writing after it, is an error.
  void commit();

  const std::filesystem::path& path() const;
  const std::filesystem::path& temporary_path() const;
  bool committed() const;

private:
  struct State;
  std::unique_ptr<State> state_;
};

// Writes `bytes` to `path` through an AtomicFileWriter.
void write_file_atomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace glint
