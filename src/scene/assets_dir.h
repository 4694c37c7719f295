#pragma once
// Finding the assets folder that scene files' mesh paths are relative to (the shared meshes live
// outside the repository, in ../shared/assets beside the checkout, and may be elsewhere on a user's
// machine).
#include "scene/load_options.h"

#include <filesystem>
#include <optional>

namespace glint {

// The first existing folder of:
//   1. options.assets_dir                      (the caller's explicit choice)
//   2. $GLINT_ASSETS                           (the user's environment)
//   3. scene_assets                            (a scene file's "assets" entry, already made absolute
//                                               or relative to the current directory by the caller)
//   4. ../shared/assets                        relative to the current directory
//   5. ../shared/assets, ../../shared/assets   relative to the running executable's folder
// Throws a glint::Error listing every place it looked, and how to point glint at the folder, when
// none exists.
std::filesystem::path find_assets_dir(const LoadOptions& options,
                                      const std::optional<std::filesystem::path>& scene_assets = std::nullopt);

}  // namespace glint
