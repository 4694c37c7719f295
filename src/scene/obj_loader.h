#pragma once
// Wavefront OBJ + MTL via tinyobjloader. Each object/group is split by material into meshes
// ("<object>/<material>"), `usemtl` materials become Materials, map_Kd textures resolve relative to
// the MTL file, missing normals are computed (smooth unless options.flat_normals). One instance per
// mesh with the identity transform.
#include "scene/load_options.h"
#include "scene/scene.h"

#include <filesystem>

namespace glint {

Scene load_obj(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace glint
