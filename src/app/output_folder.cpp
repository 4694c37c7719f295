#include "app/output_folder.h"

#include "core/error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <system_error>

namespace glint {
namespace {

std::string frame_stem(int frame) {
  if (frame < 0) fail("frame {} has no output file: frames count from 0", frame);
  return fmt::format("frame_{:05}", frame);
}

bool is_view_name_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '-';
}

}  // namespace

OutputFolder::OutputFolder(std::filesystem::path path) : path_(std::move(path)) {
  if (path_.empty()) fail("output folder: empty path");
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path_, error);
  if (std::filesystem::exists(status)) {
    if (!std::filesystem::is_directory(status))
      fail("output folder '{}' exists and is not a folder", path_.string());
    return;
  }
  std::filesystem::create_directories(path_, error);
  // create_directories also fails when a parent is a file; say which path could not be made.
  if (error) fail("cannot create output folder '{}': {}", path_.string(), error.message());
}

std::filesystem::path OutputFolder::frame_path(int frame) const { return path_ / (frame_stem(frame) + ".png"); }

std::filesystem::path OutputFolder::debug_view_path(int frame, std::string_view view) const {
  if (view.empty() || !std::all_of(view.begin(), view.end(), is_view_name_char))
    fail("debug view name '{}' must be letters, digits, '_' or '-'", view);
  std::string name = frame_stem(frame);
  name += '_';
  name += view;
  name += ".png";
  return path_ / name;
}

std::filesystem::path OutputFolder::file(std::string_view name) const {
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string_view::npos)
    fail("'{}' is not a plain file name for output folder '{}'", name, path_.string());
  return path_ / name;
}

}  // namespace glint
