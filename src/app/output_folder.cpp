#include "app/output_folder.h"

#include "core/atomic_file.h"
#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <vector>

namespace glint {
namespace {

std::string frame_stem(int frame) {
  if (frame < 0) fail("frame {} has no output file: frames count from 0", frame);
  return fmt::format("frame_{:05}", frame);
}

// The image formats a run writes; the extension without its dot.
std::string_view checked_extension(std::string_view extension) {
  if (extension != "png" && extension != "exr") fail("output folder: no image format '{}' (png or exr)", extension);
  return extension;
}

bool is_view_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

// The run's files directly in the folder (not in subfolders: bench keeps its own layout there).
std::vector<std::filesystem::path> run_outputs_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> found;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error))
    if (is_run_output_name(it->path().filename().string())) found.push_back(it->path());
  if (error) fail("output folder '{}' cannot be listed: {}", folder.string(), error.message());
  std::sort(found.begin(), found.end());
  return found;
}

// Creating a file is the only reliable test: permissions, read-only mounts and pseudo file systems
// such as /proc all answer "exists, is a folder" to a status query.
void require_writable(const std::filesystem::path& folder) {
  const std::filesystem::path probe = temporary_sibling_path(folder / "write-test");
  std::FILE* file = std::fopen(probe.c_str(), "wb");
  if (file == nullptr) fail("output folder '{}' is not writable: {}", folder.string(), std::strerror(errno));
  std::fclose(file);
  std::error_code ignored;
  std::filesystem::remove(probe, ignored);
}

}  // namespace

bool is_run_output_name(std::string_view name) {
  if (name == "run.json" || name == "timings.csv" || name == "scopes.csv" || name == "walkthrough.mp4") return true;
  if (name.starts_with("frame_") && (name.ends_with(".png") || name.ends_with(".exr"))) return true;
  return name.starts_with('.') && name.find(".tmp-") != std::string_view::npos;
}

OutputFolder::OutputFolder(std::filesystem::path path, EarlierRun earlier, std::string_view overwrite_flag)
    : path_(std::move(path)) {
  if (path_.empty()) fail("output folder: empty path");
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path_, error);
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_directory(status))
      fail("output folder '{}' exists and is not a folder", path_.string());
  } else {
    std::filesystem::create_directories(path_, error);
    // create_directories also fails when a parent is a file; say which path could not be made.
    if (error) fail("cannot create output folder '{}': {}", path_.string(), error.message());
    created_ = true;
  }
  require_writable(path_);
  if (created_ || earlier == EarlierRun::keep) return;
  const std::vector<std::filesystem::path> outputs = run_outputs_in(path_);
  if (outputs.empty()) return;
  if (earlier == EarlierRun::refuse)
    fail("output folder '{}' holds an earlier run ({} and {} more file(s)); pass {} to replace it, or choose another "
         "folder",
         path_.string(), outputs.front().filename().string(), outputs.size() - 1, overwrite_flag);
  for (const std::filesystem::path& file : outputs) {
    std::filesystem::remove(file, error);
    if (error) fail("cannot remove '{}' of the earlier run: {}", file.string(), error.message());
  }
}

OutputFolder::~OutputFolder() {
  if (!created_) return;
  std::error_code ignored;
  if (std::filesystem::is_empty(path_, ignored) && !ignored) std::filesystem::remove(path_, ignored);
}

std::filesystem::path OutputFolder::frame_path(int frame, std::string_view extension) const {
  return path_ / fmt::format("{}.{}", frame_stem(frame), checked_extension(extension));
}

std::filesystem::path OutputFolder::debug_view_path(int frame, std::string_view view,
                                                    std::string_view extension) const {
  if (view.empty() || !std::all_of(view.begin(), view.end(), is_view_name_char))
    fail("debug view name '{}' must be letters, digits, '_' or '-'", view);
  std::string name = frame_stem(frame);
  name += '_';
  name += view;
  name += '.';
  name += checked_extension(extension);
  return path_ / name;
}

std::filesystem::path OutputFolder::file(std::string_view name) const {
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string_view::npos)
    fail("'{}' is not a plain file name for output folder '{}'", name, path_.string());
  return path_ / name;
}

}  // namespace glint
