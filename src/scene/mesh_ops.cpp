#include "scene/mesh_ops.h"

#include <algorithm>
#include <cmath>

namespace glint {

namespace {

// Twice the triangle's area along its normal, in double: with float coordinates the cross product and
// its squared length would overflow from legs of about 1e19 (length from 1e9), and underflow to zero
// below about 1e-19, so huge and tiny (but valid) triangles would lose their normals or be dropped.
glm::dvec3 face_cross(const vec3& a, const vec3& b, const vec3& c) {
  return glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
}

// `v` / |v| as a float vector, or +y when v has no direction.
vec3 unit_or_up(const glm::dvec3& v) {
  const double length = glm::length(v);
  return (length > 0.0 && std::isfinite(length)) ? vec3(v / length) : vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace

void compute_smooth_normals(Mesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    // The cross product's length is twice the area, so summing it weights faces by area.
    const glm::dvec3 face = face_cross(mesh.positions[i0], mesh.positions[i1], mesh.positions[i2]);
    sum[i0] += face;
    sum[i1] += face;
    sum[i2] += face;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t v = 0; v < sum.size(); ++v) mesh.normals[v] = unit_or_up(sum[v]);
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
    const vec3 normal = unit_or_up(face_cross(a, b, c));
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
  // In double, where no float coordinate's square or fourth power overflows or underflows: legs of
  // 5e9 overflowed |e1|^2 |e2|^2 in float and a valid triangle was dropped.
  const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a), e2 = glm::dvec3(c) - glm::dvec3(a);
  const glm::dvec3 n = glm::cross(e1, e2);
  const double cross2 = glm::dot(n, n);
  const double scale2 = glm::dot(e1, e1) * glm::dot(e2, e2);
  // |e1 x e2|^2 = |e1|^2 |e2|^2 sin^2(angle): relative to the triangle's own size, so scaling a mesh
  // (any units) never changes which of its triangles are degenerate.
  return !(cross2 > 1e-12 * scale2) || scale2 == 0.0;
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
