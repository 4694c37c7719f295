#include "scene/mesh_ops.h"

#include <algorithm>

namespace glint {

void compute_smooth_normals(Mesh& mesh) {
  std::vector<vec3> sum(mesh.positions.size(), vec3(0.0f));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    // The cross product's length is twice the area, so summing it weights faces by area.
    const vec3 face = glm::cross(mesh.positions[i1] - mesh.positions[i0], mesh.positions[i2] - mesh.positions[i0]);
    sum[i0] += face;
    sum[i1] += face;
    sum[i2] += face;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const float length = glm::length(sum[v]);
    mesh.normals[v] = (length > 0.0f && std::isfinite(length)) ? sum[v] / length : vec3(0.0f, 1.0f, 0.0f);
  }
}

void compute_flat_normals(Mesh& mesh) {
  const bool has_uvs = !mesh.uvs.empty();
  std::vector<vec3> positions, normals;
  std::vector<vec2> uvs;
  positions.reserve(mesh.indices.size());
  normals.reserve(mesh.indices.size());
  if (has_uvs) uvs.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
               c = mesh.positions[mesh.indices[t + 2]];
    const vec3 face = glm::cross(b - a, c - a);
    const float length = glm::length(face);
    const vec3 normal = length > 0.0f ? face / length : vec3(0.0f, 1.0f, 0.0f);
    for (int k = 0; k < 3; ++k) {
      positions.push_back(mesh.positions[mesh.indices[t + k]]);
      normals.push_back(normal);
      if (has_uvs) uvs.push_back(mesh.uvs[mesh.indices[t + k]]);
    }
  }
  mesh.positions = std::move(positions);
  mesh.normals = std::move(normals);
  mesh.uvs = std::move(uvs);
  for (std::uint32_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = i;
}

bool is_degenerate_triangle(const vec3& a, const vec3& b, const vec3& c) {
  const vec3 e1 = b - a, e2 = c - a;
  const float cross2 = glm::dot(glm::cross(e1, e2), glm::cross(e1, e2));
  const float scale2 = glm::dot(e1, e1) * glm::dot(e2, e2);
  // |e1 x e2|^2 = |e1|^2 |e2|^2 sin^2(angle): relative test, independent of the mesh's units.
  return !(cross2 > 1e-12f * scale2) || scale2 == 0.0f;
}

std::size_t remove_degenerate_triangles(Mesh& mesh) {
  std::size_t kept = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const bool repeated = i0 == i1 || i1 == i2 || i0 == i2;
    if (repeated || is_degenerate_triangle(mesh.positions[i0], mesh.positions[i1], mesh.positions[i2])) continue;
    mesh.indices[kept++] = i0;
    mesh.indices[kept++] = i1;
    mesh.indices[kept++] = i2;
  }
  const std::size_t dropped = mesh.indices.size() / 3 - kept / 3;
  mesh.indices.resize(kept);
  return dropped;
}

}  // namespace glint
