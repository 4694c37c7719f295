#pragma once
// Step 2 of loading a scene file: SceneDescription -> Scene. Resolves mesh paths (docs/scene-format.md,
// "Paths"), loads each mesh file once, places its meshes with the entry's transform, applies material
// overrides, deformers, the floor's reflectivity, the light and the camera, then validates.
#include "scene/load_options.h"
#include "scene/scene.h"
#include "scene/scene_description.h"

#include <filesystem>

namespace glint {

Scene build_scene(const SceneDescription& description, const LoadOptions& options = {});

// The file a mesh entry refers to: absolute paths as they are; relative ones against the assets
// folder when the description has "assets" (located with find_assets_dir), else against the scene
// file's folder.
std::filesystem::path resolve_mesh_path(const SceneDescription& description, const MeshEntry& entry,
                                        const LoadOptions& options = {});

}  // namespace glint
