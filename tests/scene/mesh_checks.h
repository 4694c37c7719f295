#pragma once
// Geometric and topological checks on meshes shared by the procedural-scene tests.
#include "scene/scene.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <utility>

namespace glint::testing {

// Number of undirected edges used by other than exactly two triangles (0 for a closed 2-manifold
// surface), and whether every edge appears once in each direction (consistent orientation).
struct EdgeReport {
  std::size_t edges = 0;
  std::size_t not_shared_by_two = 0;
  std::size_t inconsistent = 0;
};

inline EdgeReport edge_report(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
    for (int e = 0; e < 3; ++e) ++directed[{mesh.indices[t + e], mesh.indices[t + (e + 1) % 3]}];
  EdgeReport report;
  for (const auto& [edge, count] : directed) {
    if (edge.first > edge.second && directed.count({edge.second, edge.first})) continue;  // counted from the other side
    const auto reverse = directed.find({edge.second, edge.first});
    const int back = reverse == directed.end() ? 0 : reverse->second;
    ++report.edges;
    if (count + back != 2) ++report.not_shared_by_two;
    if (count != 1 || back != 1) ++report.inconsistent;
  }
  return report;
}

// V - E + F.
inline long euler_characteristic(const Mesh& mesh) {
  return static_cast<long>(mesh.vertex_count()) - static_cast<long>(edge_report(mesh).edges) +
         static_cast<long>(mesh.triangle_count());
}

// Signed volume by the divergence theorem: positive when the triangles face outwards.
inline double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
               c = mesh.positions[mesh.indices[t + 2]];
    volume += static_cast<double>(glm::dot(a, glm::cross(b, c))) / 6.0;
  }
  return volume;
}

// Fraction of triangles whose geometric (winding) normal agrees with the average of their three
// stored vertex normals.
inline double fraction_winding_matches_normals(const Mesh& mesh) {
  std::size_t agree = 0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    const vec3 face = glm::cross(mesh.positions[i1] - mesh.positions[i0], mesh.positions[i2] - mesh.positions[i0]);
    if (glm::dot(face, mesh.normals[i0] + mesh.normals[i1] + mesh.normals[i2]) > 0.0f) ++agree;
  }
  return mesh.triangle_count() == 0 ? 1.0 : static_cast<double>(agree) / static_cast<double>(mesh.triangle_count());
}

}  // namespace glint::testing
