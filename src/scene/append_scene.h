#pragma once
// Merging one loaded file (a "part") into a scene under construction, for the scene JSON loader:
// copies of the part's textures, materials and meshes with their indices shifted, and its instances
// placed with an extra transform.
#include "scene/scene.h"

#include <cstdint>
#include <string_view>

namespace glint {

// Where an appended part's data landed in the scene, so that more instances of the same meshes can be
// added later without copying the geometry again (see append_instances).
struct AppendedPart {
  std::uint32_t first_mesh = 0;
  std::uint32_t mesh_count = 0;
  std::uint32_t first_material = 0;
  std::uint32_t material_count = 0;
};

// Appends copies of part.textures, part.materials and part.meshes (texture, material and mesh indices
// re-based), then one instance per part instance with transform * instance.transform. Mesh and
// instance names get `name_prefix` + "/" in front (unless the prefix is empty) so that they stay
// unique; material names are kept, since scene files refer to materials by their file's names.
AppendedPart append_scene(Scene& into, const Scene& part, const mat4& transform, std::string_view name_prefix);

// Adds instances of a part appended before (its meshes shared, not copied), placed with `transform`.
void append_instances(Scene& into, const Scene& part, const AppendedPart& where, const mat4& transform,
                      std::string_view name_prefix);

}  // namespace glint
