#include "scene/case_insensitive_path.h"

#include <algorithm>
#include <cctype>
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

}  // namespace

std::filesystem::path find_file_ignoring_case(const std::filesystem::path& folder, std::string_view name) {
  std::string portable(name);
  std::replace(portable.begin(), portable.end(), '\\', '/');
  const std::filesystem::path relative(portable);
  const std::filesystem::path exact = relative.is_absolute() ? relative : folder / relative;
  std::error_code error;
  if (std::filesystem::exists(exact, error)) return exact;

  // Walk the components, keeping each one that exists as written and matching the others.
  std::filesystem::path resolved = relative.is_absolute() ? relative.root_path() : folder;
  for (const std::filesystem::path& component : relative.relative_path()) {
    std::filesystem::path next = resolved / component;
    if (!std::filesystem::exists(next, error)) {
      next = find_entry_ignoring_case(resolved, component.string());
      if (next.empty()) return exact;
    }
    resolved = std::move(next);
  }
  return resolved;
}

}  // namespace glint
