#include "scene/assets_dir.h"

#include "core/error.h"

#include <cstdlib>
#include <string>
#include <system_error>
#include <vector>

namespace glint {
namespace {

struct Candidate {
  std::string origin;  // where the candidate came from, for the error message
  std::filesystem::path folder;
};

bool is_existing_folder(const std::filesystem::path& folder) {
  std::error_code ignored;
  return std::filesystem::is_directory(folder, ignored);
}

// The running executable's folder, or empty when /proc is unavailable.
std::filesystem::path executable_folder() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::filesystem::path() : exe.parent_path();
}

}  // namespace

std::filesystem::path find_assets_dir(const LoadOptions& options,
                                      const std::optional<std::filesystem::path>& scene_assets) {
  std::vector<Candidate> candidates;
  std::vector<std::string> not_set;
  if (options.assets_dir) candidates.push_back({"the assets option", *options.assets_dir});
  const char* env = std::getenv("GLINT_ASSETS");
  if (env != nullptr && *env != '\0') candidates.push_back({"$GLINT_ASSETS", env});
  else not_set.push_back("$GLINT_ASSETS is not set");
  if (scene_assets) candidates.push_back({"the scene's \"assets\" entry", *scene_assets});
  std::error_code no_cwd;
  const std::filesystem::path cwd = std::filesystem::current_path(no_cwd);
  candidates.push_back({"the current directory", (no_cwd ? std::filesystem::path(".") : cwd) / ".." / "shared" / "assets"});
  if (const std::filesystem::path exe = executable_folder(); !exe.empty()) {
    candidates.push_back({"the executable's folder", exe / ".." / "shared" / "assets"});
    candidates.push_back({"the executable's folder", exe / ".." / ".." / "shared" / "assets"});
  }

  for (const Candidate& candidate : candidates)
    if (is_existing_folder(candidate.folder)) return candidate.folder.lexically_normal();

  std::string looked;
  for (const Candidate& candidate : candidates)
    looked += fmt::format("{}{} (from {})", looked.empty() ? "" : ", ", candidate.folder.lexically_normal().string(),
                          candidate.origin);
  for (const std::string& note : not_set) looked += fmt::format(" ({})", note);
  // One line, like every glint::Error, so the CLI can print it as is.
  fail("assets folder not found; looked in: {}; set GLINT_ASSETS=/path/to/assets (the folder holding "
       "sponza_dabrovic/, armadillo/, ...) or pass the assets folder explicitly",
       looked);
}

}  // namespace glint
