#pragma once
// glTF 2.0 (.gltf with .bin/.png beside it, or binary .glb) via tinygltf: each primitive of each mesh
// becomes a Mesh, each node that references a mesh an Instance with the node hierarchy's world
// transform; baseColorFactor/-Texture become the diffuse colour/texture, and metallic/roughness map
// to reflectivity (documented in docs/scene-format.md).
#include "scene/load_options.h"
#include "scene/scene.h"

#include <filesystem>

namespace glint {

Scene load_gltf(const std::filesystem::path& path, const LoadOptions& options = {});

}  // namespace glint
