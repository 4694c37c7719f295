#pragma once
#include <filesystem>
#include <optional>

namespace glint {

struct LoadOptions {
  bool flat_normals = false;  // for meshes without normals: flat (per face) instead of smooth
  // Where scene files' "assets"-relative paths resolve (only scenes with an "assets" entry have them);
  // it overrides $GLINT_ASSETS, which overrides the scene's "assets"; then ../shared/assets (see
  // find_assets_dir in scene/assets_dir.h). A folder given here that does not exist is an error.
  std::optional<std::filesystem::path> assets_dir;
};

}  // namespace glint
