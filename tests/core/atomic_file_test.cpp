#include "core/atomic_file.h"
#include "core/error.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

namespace glint {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::TempFolder;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::set<std::string> names_in(const fs::path& folder) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder)) names.insert(entry.path().filename().string());
  return names;
}

// Bytes that a text-mode or C-string path would damage: NUL, CR LF, high bytes.
std::string binary_bytes(std::size_t size) {
  std::string bytes(size, '\0');
  for (std::size_t i = 0; i < size; ++i) bytes[i] = static_cast<char>((i * 131 + 7) % 256);
  return bytes;
}

TEST(AtomicFile, TemporaryIsAHiddenUniqueSiblingNamedAfterTheFile) {
  const fs::path first = temporary_sibling_path("/some/folder/frame.png");
  const fs::path second = temporary_sibling_path("/some/folder/frame.png");
  EXPECT_EQ(first.parent_path(), fs::path("/some/folder"));
  const std::string prefix = ".frame.png.tmp-" + std::to_string(::getpid()) + "-";
  EXPECT_EQ(first.filename().string().rfind(prefix, 0), 0u) << first;
  EXPECT_NE(first, second);
  EXPECT_EQ(temporary_sibling_path("relative.csv").parent_path(), fs::path());
}

TEST(AtomicFile, StaleTemporariesOfDeadProcessesAreRemoved) {
  const TempFolder temp;
  // A process id that is not running: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ::waitpid(child, nullptr, 0);
  const std::string dead = std::to_string(child), alive = std::to_string(::getpid());
  const fs::path stale = temp.write("cells/.a.csv.tmp-" + dead + "-0", "x");
  const fs::path ours = temp.write("cells/.b.csv.tmp-" + alive + "-3", "x");
  const fs::path parent = temp.write(".c.csv.tmp-" + std::to_string(::getppid()) + "-1", "x");
  const fs::path not_temporary = temp.write("cells/.notes.tmp-x-1", "x");
  const fs::path plain = temp.write("cells/a.csv", "x");
  EXPECT_EQ(remove_stale_temporaries(temp.path()), 1u);
  EXPECT_FALSE(fs::exists(stale));
  for (const fs::path& kept : {ours, parent, not_temporary, plain}) EXPECT_TRUE(fs::exists(kept)) << kept;
}

TEST(AtomicFile, CommittedContentIsExactAndNoTemporaryRemains) {
  TempFolder folder;
  const fs::path path = folder.path() / "data.bin";
  // Larger than the 64 KiB buffer and written in pieces of both kinds, so the buffered and the direct
  // paths of the stream are both exercised.
  const std::string bytes = binary_bytes(200'000);
  AtomicFileWriter writer(path);
  writer.write(std::string_view(bytes).substr(0, 10));
  writer.stream() << std::string_view(bytes).substr(10, 100'000);
  writer.write(std::string_view(bytes).substr(100'010));
  EXPECT_TRUE(fs::exists(writer.temporary_path()));
  EXPECT_FALSE(fs::exists(path));
  writer.commit();
  EXPECT_TRUE(writer.committed());
  EXPECT_EQ(read_text(path), bytes);
  EXPECT_EQ(names_in(folder.path()), std::set<std::string>{"data.bin"});
}

TEST(AtomicFile, UncommittedWriterLeavesNoFileAndNoTemporary) {
  TempFolder folder;
  fs::path temporary;
  {
    AtomicFileWriter writer(folder.path() / "never.txt");
    writer.stream() << "half of a file";
    writer.write(binary_bytes(100'000));  // some of it already reached the temporary on disk
    temporary = writer.temporary_path();
    EXPECT_TRUE(fs::exists(temporary));
  }
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_TRUE(names_in(folder.path()).empty());
}

TEST(AtomicFile, ExistingFileIsReplacedOnlyAtCommit) {
  TempFolder folder;
  const fs::path path = folder.write("table.csv", "old contents\n");
  {
    AtomicFileWriter abandoned(path);
    abandoned.stream() << "never seen\n";
  }
  EXPECT_EQ(read_text(path), "old contents\n");

  AtomicFileWriter writer(path);
  writer.stream() << "new contents\n";
  writer.stream().flush();  // on disk in the temporary, still not under the final name
  EXPECT_EQ(read_text(path), "old contents\n");
  writer.commit();
  EXPECT_EQ(read_text(path), "new contents\n");
  EXPECT_EQ(names_in(folder.path()), std::set<std::string>{"table.csv"});
}

TEST(AtomicFile, MissingFolderIsAnErrorNamingThePath) {
  TempFolder folder;
  const fs::path path = folder.path() / "missing" / "out.txt";
  const std::string message = error_of([&] { AtomicFileWriter writer(path); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("does not exist"), std::string::npos) << message;
  EXPECT_TRUE(names_in(folder.path()).empty());
}

TEST(AtomicFile, FolderThatIsAFileIsAnErrorNamingThePath) {
  TempFolder folder;
  const fs::path file = folder.write("plain.txt", "x");
  const fs::path path = file / "out.txt";
  const std::string message = error_of([&] { write_file_atomically(path, "data"); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("is not a folder"), std::string::npos) << message;
}

TEST(AtomicFile, UnwritableFolderIsAnErrorWithStrerror) {
  if (::geteuid() == 0) GTEST_SKIP() << "root ignores folder permissions";
  TempFolder folder;
  const fs::path locked = folder.path() / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const fs::path path = locked / "out.txt";
  const std::string message = error_of([&] { write_file_atomically(path, "data"); });
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
}

TEST(AtomicFile, FailedRenameNamesThePathAndRemovesTheTemporary) {
  TempFolder folder;
  const fs::path path = folder.path() / "taken";
  fs::create_directories(path / "child");  // a non-empty folder cannot be replaced by a file
  AtomicFileWriter writer(path);
  writer.stream() << "data";
  const std::string message = error_of([&] { writer.commit(); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_FALSE(writer.committed());
  EXPECT_EQ(names_in(folder.path()), std::set<std::string>{"taken"});
  EXPECT_TRUE(fs::is_directory(path / "child"));
}

TEST(AtomicFile, CommittingTwiceOrWritingAfterCommitIsAnError) {
  TempFolder folder;
  const fs::path path = folder.path() / "once.txt";
  AtomicFileWriter writer(path);
  writer.write("one");
  writer.commit();
  EXPECT_NE(error_of([&] { writer.commit(); }).find(path.string()), std::string::npos);
  EXPECT_NE(error_of([&] { writer.write("two"); }).find(path.string()), std::string::npos);
  // The stream fails too, rather than writing into whatever file reuses the closed descriptor.
  writer.stream() << binary_bytes(100'000);
  EXPECT_TRUE(writer.stream().bad());
  EXPECT_EQ(read_text(path), "one");
}

TEST(AtomicFile, MovedWriterOwnsTheFile) {
  TempFolder folder;
  const fs::path path = folder.path() / "moved.txt";
  AtomicFileWriter first(path);
  first.write("abc");
  AtomicFileWriter second(std::move(first));
  second.write("def");
  second.commit();
  EXPECT_EQ(read_text(path), "abcdef");

  // Assigning over a live writer abandons its file.
  AtomicFileWriter target(folder.path() / "abandoned.txt");
  const fs::path abandoned_temporary = target.temporary_path();
  target = AtomicFileWriter(folder.path() / "kept.txt");
  EXPECT_FALSE(fs::exists(abandoned_temporary));
  target.write("kept");
  target.commit();
  EXPECT_EQ(names_in(folder.path()), (std::set<std::string>{"kept.txt", "moved.txt"}));
}

TEST(AtomicFile, WriteFileAtomicallyWritesExactBytes) {
  TempFolder folder;
  const fs::path path = folder.path() / "bytes.bin";
  const std::string bytes = binary_bytes(1000);
  write_file_atomically(path, bytes);
  EXPECT_EQ(read_text(path), bytes);
  write_file_atomically(path, "");
  EXPECT_TRUE(fs::exists(path));
  EXPECT_EQ(fs::file_size(path), 0u);
}

// A file-size limit makes write(2) fail with EFBIG, standing in for a full disk: the error must carry
// strerror, and nothing may appear under the final name.
TEST(AtomicFile, WriteErrorIsReportedWithStrerrorAndLeavesNoFile) {
  TempFolder folder;
  const fs::path path = folder.path() / "big.bin";
  rlimit old_limit{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &old_limit), 0);
  void (*old_handler)(int) = std::signal(SIGXFSZ, SIG_IGN);  // else the kernel kills the process
  rlimit small = old_limit;
  small.rlim_cur = 1000;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  std::string message;
  {
    AtomicFileWriter writer(path);
    message = error_of([&] {
      writer.write(binary_bytes(100'000));
      writer.commit();
    });
  }
  ::setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
  EXPECT_NE(message.find(std::strerror(EFBIG)), std::string::npos) << message;
  EXPECT_TRUE(names_in(folder.path()).empty());
}

}  // namespace
}  // namespace glint
