#include "scene/obj_materials.h"

#include "core/log.h"
#include "core/untrusted_text.h"
#include "scene/case_insensitive_path.h"
#include "scene/file_text.h"
#include "scene/obj_text_parsing.h"
#include "scene/texture_io.h"

#include <algorithm>
#include <map>
#include <set>

namespace glint {
namespace {

// The files one `mtllib` line names. The spec allows several, separated by blanks, but exporters
// also write one name with spaces in it: the whole text is taken as one name when that file exists.
std::vector<std::string> library_file_names(const std::filesystem::path& folder, std::string_view names) {
  std::error_code error;
  if (std::filesystem::exists(find_file_ignoring_case(folder, names), error)) return {std::string(names)};
  std::vector<std::string> result;
  for (std::string_view name = obj_text::take_token(names); !name.empty(); name = obj_text::take_token(names))
    result.emplace_back(name);
  return result;
}

void add_library_file(ObjMaterialLibrary& library, const std::filesystem::path& mtl_path) {
  const std::string text = read_file_text(mtl_path);
  for (MtlMaterial& material : read_mtl_text(text, mtl_path.string())) {
    if (library.find(material.material.name) >= 0) {
      log_warning("{}:{}: material '{}' is already defined by an earlier material library; that one is used",
                  mtl_path.string(), material.line, untrusted_text(material.material.name));
      continue;
    }
    library.materials.push_back(std::move(material));
    library.material_files.push_back(mtl_path);
  }
}

void warn_about_undefined_materials(const ObjMaterialLibrary& library, const ObjTextSummary& summary,
                                    std::string_view obj_label, bool a_library_is_missing) {
  std::vector<const ObjLineReference*> undefined;
  for (const ObjLineReference& use : summary.materials_used)
    if (library.find(use.name) < 0) undefined.push_back(&use);
  if (undefined.empty()) return;
  if (a_library_is_missing) {
    // The missing library is the cause: one warning rather than one per material name.
    log_warning("{}:{}: {} material name{} ('{}'{}) {} not defined because a material library is missing; "
                "{} faces use the default material",
                obj_label, undefined.front()->line, undefined.size(), undefined.size() == 1 ? "" : "s",
                untrusted_text(undefined.front()->name), undefined.size() > 1 ? ", ..." : "", undefined.size() == 1 ? "is" : "are",
                undefined.size() == 1 ? "its" : "their");
    return;
  }
  for (const ObjLineReference* use : undefined)
    log_warning("{}:{}: material '{}' is not defined in any material library; its faces use the default material",
                obj_label, use->line, untrusted_text(use->name));
}

}  // namespace

int ObjMaterialLibrary::find(std::string_view name) const {
  for (std::size_t i = 0; i < materials.size(); ++i)
    if (materials[i].material.name == name) return static_cast<int>(i);
  return -1;
}

std::vector<std::string> ObjMaterialLibrary::names() const {
  std::vector<std::string> result;
  result.reserve(materials.size());
  for (const MtlMaterial& material : materials) result.push_back(material.material.name);
  return result;
}

ObjMaterialLibrary load_obj_material_library(const std::filesystem::path& obj_path, const ObjTextSummary& summary) {
  ObjMaterialLibrary library;
  const std::filesystem::path folder = obj_path.parent_path();
  std::set<std::filesystem::path> loaded;
  bool a_library_is_missing = false;
  for (const ObjLineReference& line : summary.material_libraries) {
    for (const std::string& name : library_file_names(folder, line.name)) {
      const std::filesystem::path mtl_path = find_file_ignoring_case(folder, name);
      std::error_code error;
      if (!std::filesystem::exists(mtl_path, error)) {
        log_warning("{}:{}: material library '{}' not found; its materials fall back to the default material",
                    obj_path.string(), line.line, untrusted_text(mtl_path.string()));
        a_library_is_missing = true;
        continue;
      }
      if (loaded.insert(mtl_path.lexically_normal()).second) add_library_file(library, mtl_path);
    }
  }
  warn_about_undefined_materials(library, summary, obj_path.string(), a_library_is_missing);
  return library;
}

std::vector<std::uint32_t> add_obj_materials(const ObjMaterialLibrary& library, const std::vector<int>& used, Scene& scene) {
  std::vector<int> distinct(used.begin(), used.end());
  std::sort(distinct.begin(), distinct.end());
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  // Library order with -1 ("default") last.
  std::stable_partition(distinct.begin(), distinct.end(), [](int index) { return index >= 0; });

  std::map<int, std::uint32_t> scene_index_of;
  std::map<std::filesystem::path, int> texture_of_file;
  for (const int index : distinct) {
    scene_index_of[index] = static_cast<std::uint32_t>(scene.materials.size());
    if (index < 0) {
      scene.materials.push_back(Material{});  // named "default"
      continue;
    }
    const MtlMaterial& entry = library.materials[static_cast<std::size_t>(index)];
    Material material = entry.material;
    if (!entry.diffuse_map.empty()) {
      const std::filesystem::path& mtl_path = library.material_files[static_cast<std::size_t>(index)];
      const std::filesystem::path file = find_file_ignoring_case(mtl_path.parent_path(), entry.diffuse_map);
      const auto [it, inserted] = texture_of_file.try_emplace(file.lexically_normal(), static_cast<int>(scene.textures.size()));
      if (inserted)
        scene.textures.push_back(load_texture_or_placeholder(file, fmt::format("{}:{}", mtl_path.string(), entry.diffuse_map_line)));
      material.diffuse_texture = it->second;
    }
    scene.materials.push_back(std::move(material));
  }

  std::vector<std::uint32_t> result;
  result.reserve(used.size());
  for (const int index : used) result.push_back(scene_index_of.at(index));
  return result;
}

}  // namespace glint
