#pragma once
// Turns tinyobjloader's shapes into glint meshes: one mesh per (shape, material), vertices shared
// within a mesh when their (v, vt, vn) index triple is the same.
#include "scene/scene.h"

#include <tiny_obj_loader.h>

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

struct ObjMeshPart {
  Mesh mesh;          // positions, indices, UVs and file normals as described below; `material` unset
  int material = -1;  // index into the material list given to assemble_obj_meshes, -1 for none
};

// Faces are grouped by (shape name, material) in the order they first appear, so an object that
// switches materials becomes one mesh per material, named "<shape>/<material>", or "<shape>" when
// the shape uses one material (faces without one count as material "default"). A shape without a
// name is called `unnamed_shape`. Faces of more than three corners are split by triangulate_polygon
// (scene/polygon_triangulation.h). Per mesh:
// - uvs: filled when any face has texture coordinates (corners without one get (0, 0)), else empty;
// - normals: the file's normals, normalised, when every corner has one and none is zero-length;
//   otherwise left empty for the caller to compute (a mix of given and computed normals would shade
//   inconsistently). With `smoothing_groups` (the file has `s` lines), corners without a normal are
//   shared only within their face's smoothing group, and not at all under "s off", so that computed
//   smooth normals follow the groups (flat faces under "s off").
// `face_vertex_counts` is every face's vertex count in file order (ObjTextSummary's, which the
// caller has checked against the shapes: tinyobjloader's own are 8-bit). `face_materials` is every
// face's material in file order, an index into `material_names` (-1: none).
std::vector<ObjMeshPart> assemble_obj_meshes(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                                             std::span<const std::uint16_t> face_vertex_counts, bool smoothing_groups,
                                             const std::vector<int>& face_materials,
                                             const std::vector<std::string>& material_names,
                                             std::string_view unnamed_shape);

}  // namespace glint
