#include "scene/obj_mesh_assembly.h"

#include "scene/polygon_triangulation.h"

#include <cstdint>
#include <map>
#include <span>
#include <unordered_map>
#include <utility>

namespace glint {
namespace {

struct VertexKey {
  int position;
  int texcoord;  // -1 when the corner has none
  int normal;    // -1 when the corner has none
  // Without a normal, corners of different smoothing groups are different vertices, so that computed
  // normals are smooth within a group only: the group (> 0), minus one minus the file's face number
  // for a face under "s off" (its own vertices: flat), or 0 (no groups in the file, or a normal given).
  long long smoothing;
  bool operator==(const VertexKey&) const = default;
};

struct VertexKeyHash {
  std::size_t operator()(const VertexKey& key) const {
    constexpr std::uint64_t kMultiplier = 0x9E3779B97F4A7C15ull;  // 2^64 / golden ratio
    std::uint64_t hash = static_cast<std::uint32_t>(key.position);
    hash = (hash * kMultiplier) ^ static_cast<std::uint32_t>(key.texcoord);
    hash = (hash * kMultiplier) ^ static_cast<std::uint32_t>(key.normal);
    hash = (hash * kMultiplier) ^ static_cast<std::uint64_t>(key.smoothing);
    return static_cast<std::size_t>(hash ^ (hash >> 31));
  }
};

// One mesh under construction: its distinct corners and the triangles that use them.
struct PartBuilder {
  std::string shape;
  int material = -1;
  std::vector<VertexKey> vertices;
  std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> vertex_of_key;
  std::vector<std::uint32_t> indices;

  void add_corner(const tinyobj::index_t& corner, long long smoothing) {
    const VertexKey key{corner.vertex_index, corner.texcoord_index, corner.normal_index,
                        corner.normal_index < 0 ? smoothing : 0};
    const auto [it, inserted] = vertex_of_key.try_emplace(key, static_cast<std::uint32_t>(vertices.size()));
    if (inserted) vertices.push_back(key);
    indices.push_back(it->second);
  }
};

vec3 read_vec3(const std::vector<tinyobj::real_t>& values, int index) {
  const std::size_t at = static_cast<std::size_t>(index) * 3;
  return vec3(values[at], values[at + 1], values[at + 2]);
}

Mesh finish_mesh(PartBuilder& part, const tinyobj::attrib_t& attrib) {
  Mesh mesh;
  mesh.indices = std::move(part.indices);
  mesh.positions.reserve(part.vertices.size());
  bool any_uv = false, every_normal = true;
  for (const VertexKey& key : part.vertices) {
    mesh.positions.push_back(read_vec3(attrib.vertices, key.position));
    any_uv = any_uv || key.texcoord >= 0;
    every_normal = every_normal && key.normal >= 0;
  }
  if (any_uv) {
    mesh.uvs.reserve(part.vertices.size());
    for (const VertexKey& key : part.vertices) {
      const std::size_t at = static_cast<std::size_t>(key.texcoord) * 2;  // tinyobjloader keeps u, v
      mesh.uvs.push_back(key.texcoord >= 0 ? vec2(attrib.texcoords[at], attrib.texcoords[at + 1]) : vec2(0.0f));
    }
  }
  if (every_normal) {
    mesh.normals.reserve(part.vertices.size());
    for (const VertexKey& key : part.vertices) {
      const vec3 normal = read_vec3(attrib.normals, key.normal);
      const float length = glm::length(normal);
      if (!(length > 0.0f)) {
        mesh.normals.clear();  // a zero normal: compute them all instead
        break;
      }
      mesh.normals.push_back(normal / length);
    }
  }
  return mesh;
}

}  // namespace

std::vector<ObjMeshPart> assemble_obj_meshes(const tinyobj::attrib_t& attrib, const std::vector<tinyobj::shape_t>& shapes,
                                             std::span<const std::uint16_t> face_vertex_counts, bool smoothing_groups,
                                             const std::vector<int>& face_materials,
                                             const std::vector<std::string>& material_names,
                                             std::string_view unnamed_shape) {
  std::vector<PartBuilder> parts;
  // (shape name, material) -> index into parts. tinyobjloader starts a new shape_t at every
  // `usemtl`, so the same name can come back many times; those faces belong together.
  std::map<std::pair<std::string, int>, std::size_t> part_of_key;
  std::vector<vec3> polygon;  // one polygonal face's positions, reused
  std::size_t file_face = 0;  // the face's place among all `f` lines of the file
  for (const tinyobj::shape_t& shape : shapes) {
    const std::string shape_name = shape.name.empty() ? std::string(unnamed_shape) : shape.name;
    std::size_t offset = 0;
    for (std::size_t face = 0; face < shape.mesh.num_face_vertices.size(); ++face) {
      const std::size_t corners = face_vertex_counts[file_face];
      // Faces come untriangulated (tinyobjloader's triangulation breaks concave polygons):
      // polygons are split here, in their own plane.
      if (corners >= 3) {
        const int material = face_materials[file_face];
        const auto [it, inserted] = part_of_key.try_emplace({shape_name, material}, parts.size());
        if (inserted) parts.push_back(PartBuilder{shape_name, material, {}, {}, {}});
        PartBuilder& part = parts[it->second];
        const std::span<const tinyobj::index_t> face_corners(shape.mesh.indices.data() + offset, corners);
        const unsigned group = face < shape.mesh.smoothing_group_ids.size() ? shape.mesh.smoothing_group_ids[face] : 0u;
        const long long smoothing =
            !smoothing_groups ? 0 : group > 0 ? static_cast<long long>(group) : -1 - static_cast<long long>(file_face);
        if (corners == 3) {
          for (const tinyobj::index_t& corner : face_corners) part.add_corner(corner, smoothing);
        } else {
          polygon.clear();
          for (const tinyobj::index_t& corner : face_corners) polygon.push_back(read_vec3(attrib.vertices, corner.vertex_index));
          for (const std::array<std::uint32_t, 3>& triangle : triangulate_polygon(polygon))
            for (const std::uint32_t k : triangle) part.add_corner(face_corners[k], smoothing);
        }
      }
      offset += corners;
      ++file_face;
    }
  }

  std::map<std::string, int> materials_per_shape;
  for (const PartBuilder& part : parts) ++materials_per_shape[part.shape];

  std::vector<ObjMeshPart> result;
  result.reserve(parts.size());
  for (PartBuilder& part : parts) {
    ObjMeshPart finished{finish_mesh(part, attrib), part.material};
    const std::string material_name = part.material >= 0 ? material_names[static_cast<std::size_t>(part.material)] : "default";
    finished.mesh.name = materials_per_shape[part.shape] > 1 ? part.shape + "/" + material_name : part.shape;
    result.push_back(std::move(finished));
    part = PartBuilder{};  // release the lookup table early: Sponza-sized files have many of them
  }
  return result;
}

}  // namespace glint
