#pragma once
// Finding the assets folder that scene files' mesh paths are relative to (the shared meshes live
// outside the repository, in ../shared/assets beside the checkout, and may be elsewhere on a user's
// machine).
#include "scene/load_options.h"

#include <filesystem>
#include <optional>

namespace glint {

// The first of these that is given:
//   1. options.assets_dir                      (the caller's explicit choice, e.g. --assets)
//   2. $GLINT_ASSETS                           (the user's environment)
//   3. scene_assets                            (a scene file's "assets" entry, already made absolute
//                                               or relative to the current directory by the caller)
// A folder given this way must exist: else a glint::Error "assets folder not found: '<folder>', given
// by <which of the three>, ..." (no silent fallback to other meshes). When none is given, the first
// existing folder of:
//   4. ../shared/assets                        relative to the current directory
//   5. ../shared/assets, ../../shared/assets   relative to the running executable's folder
// and a glint::Error listing every place it looked, and how to point glint at the folder, when none
// exists.
std::filesystem::path find_assets_dir(const LoadOptions& options,
                                      const std::optional<std::filesystem::path>& scene_assets = std::nullopt);

}  // namespace glint
