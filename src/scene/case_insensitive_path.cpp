#include "scene/case_insensitive_path.h"

#include <algorithm>
#include <cctype>
#include <iterator>
#include <string>
#include <system_error>

namespace glint {
namespace {

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) == std::tolower(static_cast<unsigned char>(y));
         });
}

// The entry of `folder` whose name equals `component` up to case, or an empty path.
std::filesystem::path find_entry_ignoring_case(const std::filesystem::path& folder, const std::string& component) {
  std::error_code error;
  const std::filesystem::path listed = folder.empty() ? std::filesystem::path(".") : folder;
  for (std::filesystem::directory_iterator it(listed, error), end; !error && it != end; it.increment(error))
    if (equal_ignoring_case(it->path().filename().string(), component)) return folder / it->path().filename();
  return {};
}

// `start` / the components [first, last), keeping each one that exists as written and matching the
// others ignoring case; an empty path when one matches nothing.
std::filesystem::path walk_ignoring_case(std::filesystem::path start, std::filesystem::path::iterator first,
                                         std::filesystem::path::iterator last) {
  std::error_code error;
  for (; first != last; ++first) {
    std::filesystem::path next = start / *first;
    if (!std::filesystem::exists(next, error)) {
      next = find_entry_ignoring_case(start, first->string());
      if (next.empty()) return {};
    }
    start = std::move(next);
  }
  return start;
}

}  // namespace

std::filesystem::path find_file_ignoring_case(const std::filesystem::path& folder, std::string_view name) {
  std::string portable(name);
  std::replace(portable.begin(), portable.end(), '\\', '/');
  const std::filesystem::path relative(portable);
  const std::filesystem::path exact = relative.is_absolute() ? relative : folder / relative;
  std::error_code error;
  if (std::filesystem::exists(exact, error)) return exact;

  const std::filesystem::path components = relative.relative_path();
  const std::filesystem::path found = walk_ignoring_case(relative.is_absolute() ? relative.root_path() : folder,
                                                         components.begin(), components.end());
  if (!found.empty() || components.empty()) return found.empty() ? exact : found;
  // A path from the author's machine (C:\Users\...\Textures\wall.jpg, /home/...) or one that climbs
  // out of the folder: its trailing components beside `folder`, the longest first, down to the name.
  for (auto first = std::next(components.begin()); first != components.end(); ++first)
    if (const std::filesystem::path tail = walk_ignoring_case(folder, first, components.end()); !tail.empty()) return tail;
  return exact;
}

}  // namespace glint
