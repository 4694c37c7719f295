#pragma once
// A fast line-level check of an OBJ file's text that runs before tinyobjloader. tinyobjloader is
// lenient: it reads "v 1 x 2" as (1, 0, 2), keeps NaN positions, and reports bad face indices
// without a line number, if at all. This pass rejects all of that with one glint::Error
// "<file>:<line>: <what is wrong>", and collects the `mtllib`/`usemtl` references (with their lines)
// that the material stage needs for its warnings.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

// The most vertices an OBJ face ('f' line) may have (docs/scene-format.md, "Limits"): a polygon is
// triangulated by ear clipping (polygon_triangulation.h) in time quadratic in its vertex count or
// worse, so one crafted line could hold glint for minutes. Real models' faces are triangles and
// quads, and n-gons of tens to hundreds of vertices.
inline constexpr std::size_t kMaxObjFaceVertices = 1024;

struct ObjLineReference {
  std::string name;
  std::size_t line = 0;
};

struct ObjTextSummary {
  std::size_t position_count = 0;  // `v` lines
  std::size_t texcoord_count = 0;  // `vt` lines
  std::size_t normal_count = 0;    // `vn` lines
  // Each `f` line's vertex count, in file order (tinyobjloader keeps them in 8 bits: a face of 256
  // or more vertices would come back as count % 256).
  std::vector<std::uint16_t> face_vertex_counts;
  // Any `s` line: the file says which faces are smoothed together ("s off" or "s 0": none), which
  // decides the normals of faces that have none.
  bool smoothing_groups = false;
  std::vector<ObjLineReference> material_libraries;  // each `mtllib` line's file name(s), as written
  std::vector<ObjLineReference> materials_used;      // each distinct `usemtl` name, at its first use
  // Per `f` line, in file order: the index into materials_used of the `usemtl` in force, -1 before
  // any. Names are the whole rest of the line ("usemtl 01 - Default"), which tinyobjloader's
  // first-word lookup would merge, so faces get their materials from here.
  std::vector<std::int32_t> face_materials;
};

// Checks, line by line: `v` has 3 to 7 numbers (x y z [w] or x y z r g b) and a finite position;
// `vt` has 1 to 3 finite numbers; `vn` has 3; `f` has 3 to kMaxObjFaceVertices vertices, `l` at
// least 2 and `p` 1, each
// "v", "v/vt", "v//vn" or "v/vt/vn" with indices that are not 0 and refer to an element defined
// before the line (negative indices count back from the last one); `usemtl` and `mtllib` name
// something. Other statements (o, g, s, comments, ...) are left to tinyobjloader. Throws if the file
// has no faces at all. `file_label` is the name used in messages.
ObjTextSummary validate_obj_text(std::string_view text, std::string_view file_label);

}  // namespace glint
