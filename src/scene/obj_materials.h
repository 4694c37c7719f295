#pragma once
// The material side of an OBJ file: its MTL libraries, the `usemtl` names they do not define, and
// turning the materials that meshes use into Scene materials and textures.
#include "scene/mtl_reader.h"
#include "scene/obj_validation.h"
#include "scene/scene.h"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct ObjMaterialLibrary {
  std::vector<MtlMaterial> materials;                    // every MTL file's materials, in order, names unique
  std::vector<std::filesystem::path> material_files;     // for each material: the MTL file that defines it

  int find(std::string_view name) const;                 // index into materials, -1 when not defined
  std::vector<std::string> names() const;
};

// Reads and checks the MTL files named by the OBJ's `mtllib` lines (relative to the OBJ's folder,
// case-insensitively when the exact name is missing). A malformed MTL throws (naming the .mtl file
// and line); a missing one is a warning naming the OBJ file and line. Then warns about `usemtl`
// names that no library defines: their faces get the default material.
ObjMaterialLibrary load_obj_material_library(const std::filesystem::path& obj_path, const ObjTextSummary& summary);

// Appends to scene.materials the library materials listed in `used` (library indices; -1 stands
// for faces without a material and adds one "default" material), in library order with "default"
// last, and loads their map_Kd textures into scene.textures, each file once however many materials
// share it. Returns, for each entry of `used`, its index in scene.materials.
std::vector<std::uint32_t> add_obj_materials(const ObjMaterialLibrary& library, const std::vector<int>& used, Scene& scene);

}  // namespace glint
