#pragma once
// Resolving file names written in scene files (MTL map_Kd, ...) that were authored on Windows: the
// case often differs from the file on disk ("Textures/Wall.JPG" for textures/wall.jpg) and the
// separator may be a backslash.
#include <filesystem>
#include <string_view>

namespace glint {

// `name` relative to `folder` (or as is when absolute), with '\' read as '/'. When that file does not
// exist, each path component that is missing is matched case-insensitively against its folder's
// entries; when that finds nothing either, the name's trailing components are tried beside
// `folder`, longest first, down to the file name alone (a path from the author's machine,
// "C:\Users\me\model\Textures\wall.jpg", finds Textures/wall.jpg or wall.jpg next to the MTL).
// Returns the existing file, or the exact (not found) path when nothing matches.
std::filesystem::path find_file_ignoring_case(const std::filesystem::path& folder, std::string_view name);

}  // namespace glint
