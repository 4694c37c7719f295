#include "scene/assets_dir.h"

#include "core/error.h"
#include "core/untrusted_text.h"

#include <cstdlib>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace glint {
namespace {

constexpr const char* kHowToPointGlintAtTheAssets =
    "set GLINT_ASSETS=/path/to/assets (the folder holding sponza_dabrovic/, armadillo/, ...; ../shared/assets "
    "beside the checkout) or pass the assets folder explicitly";

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
  // A folder someone named is used or is an error: falling back to another folder would load other
  // meshes than the ones asked for, without a word.
  std::optional<Candidate> named;
  const char* env = std::getenv("GLINT_ASSETS");
  if (options.assets_dir) named = Candidate{"the assets option (--assets)", *options.assets_dir};
  else if (env != nullptr && *env != '\0') named = Candidate{"$GLINT_ASSETS", env};
  else if (scene_assets) named = Candidate{"the scene's \"assets\" entry", *scene_assets};
  if (named) {
    if (is_existing_folder(named->folder)) return named->folder.lexically_normal();
    fail("assets folder not found: '{}', given by {}, is not a folder; {}", untrusted_text(named->folder.string()),
         named->origin, kHowToPointGlintAtTheAssets);
  }

  std::vector<Candidate> candidates;
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
  // One line, like every glint::Error, so the CLI can print it as is.
  fail("assets folder not found; looked in: {} ($GLINT_ASSETS is not set); {}", looked, kHowToPointGlintAtTheAssets);
}

}  // namespace glint
