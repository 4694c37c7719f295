#pragma once
#include <filesystem>
#include <optional>

namespace glint {

struct LoadOptions {
  bool flat_normals = false;  // for meshes without normals: flat (per face) instead of smooth
  // Where scene files' "assets"-relative paths resolve; unset: the scene file's own "assets" entry,
  // then $GLINT_ASSETS, then ../shared/assets (see find_assets_dir).
  std::optional<std::filesystem::path> assets_dir;
};

}  // namespace glint
