// Wavefront OBJ loading in four stages, each in its own file:
//   1 obj_validation     one fast pass over the text: malformed lines become "file.obj:LINE: ..." errors
//   2 obj_materials      the MTL libraries (mtl_reader), with warnings for missing files and names
//   3 tinyobjloader      geometry (faces left as polygons: its triangulation breaks concave ones;
//                        each face's material comes from the validation pass, names whole)
//   4 obj_mesh_assembly  meshes per (object, material), polygons split by polygon_triangulation, then
//                        degenerate removal and normals here
// How MTL statements map onto glint::Material is documented in mtl_reader.h.
#include "scene/obj_loader.h"

#include "core/error.h"
#include "core/log.h"
#include "core/untrusted_text.h"
#include "scene/default_walkthrough.h"
#include "scene/file_text.h"
#include "scene/mesh_ops.h"
#include "scene/obj_materials.h"
#include "scene/obj_mesh_assembly.h"
#include "scene/obj_validation.h"

#include <tiny_obj_loader.h>

namespace glint {
namespace {

// Each face's material as a library index (-1: none or undefined), from the validation pass's
// `usemtl` names: tinyobjloader's own ids look names up by their first word only.
std::vector<int> library_index_of_faces(const ObjTextSummary& summary, const ObjMaterialLibrary& library) {
  std::vector<int> of_used;
  of_used.reserve(summary.materials_used.size());
  for (const ObjLineReference& use : summary.materials_used) of_used.push_back(library.find(use.name));
  std::vector<int> result;
  result.reserve(summary.face_materials.size());
  for (const std::int32_t used : summary.face_materials) result.push_back(used >= 0 ? of_used[static_cast<std::size_t>(used)] : -1);
  return result;
}

// tinyobjloader and obj_validation can disagree on what a vertex line is (tinyobjloader separates
// tokens by spaces and tabs only: "v\v0 1 0" is a vertex to the validation pass but not to it), and
// then a face index the validation accepted runs past tinyobjloader's arrays (a heap over-read found
// by fuzz/, input in fuzz/regressions/obj_mtl/). Every index is checked against what was read.
void check_face_indices(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                        const std::string& file_label) {
  const auto fits = [](int index, std::size_t values, std::size_t per_element) {
    return index < 0 || static_cast<std::size_t>(index) < values / per_element;  // -1: not given
  };
  for (const tinyobj::shape_t& shape : shapes)
    for (const tinyobj::index_t& index : shape.mesh.indices)
      if (!fits(index.vertex_index, attrib.vertices.size(), 3) || !fits(index.normal_index, attrib.normals.size(), 3) ||
          !fits(index.texcoord_index, attrib.texcoords.size(), 2))
        fail("{}: a face refers to an element that tinyobjloader did not read ({} v, {} vt, {} vn read; separate the "
             "numbers of v, vt and vn lines with spaces or tabs)",
             file_label, attrib.vertices.size() / 3, attrib.texcoords.size() / 2, attrib.normals.size() / 3);
}

// The faces untriangulated, as the validation pass counted them: the same faces in the same order,
// each with as many corners (tinyobjloader's counts are 8-bit, so only count % 256 can be compared).
// A disagreement would split the corner list at the wrong places.
void check_face_vertex_counts(const std::vector<tinyobj::shape_t>& shapes, const ObjTextSummary& summary,
                              const std::string& file_label) {
  const std::vector<std::uint16_t>& counts = summary.face_vertex_counts;
  std::size_t face = 0, corners = 0, tinyobj_corners = 0;
  bool agree = true;
  for (const tinyobj::shape_t& shape : shapes) {
    tinyobj_corners += shape.mesh.indices.size();
    for (const unsigned char count : shape.mesh.num_face_vertices) {
      agree = agree && face < counts.size() && count == counts[face] % 256;
      if (face < counts.size()) corners += counts[face];
      ++face;
    }
  }
  if (!agree || face != counts.size() || corners != tinyobj_corners)
    fail("{}: tinyobjloader read {} faces with {} vertex references where glint read {} 'f' lines (separate an 'f' "
         "line's keyword and vertex references with spaces or tabs)",
         file_label, face, tinyobj_corners, counts.size());
}

// Drops zero-area triangles (one warning for the file) and the meshes left without any.
void remove_degenerate_geometry(std::vector<ObjMeshPart>& parts, const std::string& file_label) {
  std::size_t dropped = 0;
  for (ObjMeshPart& part : parts) dropped += remove_degenerate_triangles(part.mesh);
  if (dropped > 0)
    log_warning("{}: dropped {} degenerate (zero-area) triangle{}", file_label, dropped, dropped == 1 ? "" : "s");
  std::erase_if(parts, [](const ObjMeshPart& part) { return part.mesh.indices.empty(); });
}

}  // namespace

Scene load_obj(const std::filesystem::path& path, const LoadOptions& options) {
  const std::string file_label = path.string();
  const std::string text = read_file_text(path);
  const ObjTextSummary summary = validate_obj_text(text, file_label);
  const ObjMaterialLibrary library = load_obj_material_library(path, summary);

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // obj_mesh_assembly splits polygons (polygon_triangulation.h)
  config.vertex_color = false;  // glint has no vertex colours; skip filling them
  tinyobj::ObjReader reader;
  // tinyobjloader reads the geometry only: materials come from our own MTL reader (which checks
  // them and knows which folder each material's textures are relative to) and each face's material
  // from the validation pass, so it is given no material text (its `usemtl` lookups fail quietly).
  // The validation pass has rejected everything tinyobjloader is known to fail on; this is a backstop.
  if (!reader.ParseFromString(text, std::string(), config))
    fail("{}: {}", file_label,
         reader.Error().empty() ? "tinyobjloader could not parse the file" : untrusted_text(reader.Error()));
  if (!reader.Warning().empty()) log_debug("{}: tinyobjloader: {}", file_label, untrusted_text(reader.Warning()));

  check_face_indices(reader.GetAttrib(), reader.GetShapes(), file_label);
  check_face_vertex_counts(reader.GetShapes(), summary, file_label);
  std::vector<ObjMeshPart> parts =
      assemble_obj_meshes(reader.GetAttrib(), reader.GetShapes(), summary.face_vertex_counts, summary.smoothing_groups,
                          library_index_of_faces(summary, library), library.names(), path.stem().string());
  remove_degenerate_geometry(parts, file_label);
  for (ObjMeshPart& part : parts) {
    if (!part.mesh.normals.empty()) continue;
    if (options.flat_normals)
      compute_flat_normals(part.mesh);
    else
      compute_smooth_normals(part.mesh);
  }

  Scene scene;
  scene.name = path.stem().string();
  scene.source = file_label;
  std::vector<int> used;
  used.reserve(parts.size());
  for (const ObjMeshPart& part : parts) used.push_back(part.material);
  const std::vector<std::uint32_t> scene_material = add_obj_materials(library, used, scene);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    parts[i].mesh.material = scene_material[i];
    scene.instances.push_back(Instance{parts[i].mesh.name, static_cast<std::uint32_t>(scene.meshes.size()), mat4(1.0f)});
    scene.meshes.push_back(std::move(parts[i].mesh));
  }

  assign_default_walkthrough(scene);
  scene.validate();
  return scene;
}

}  // namespace glint
