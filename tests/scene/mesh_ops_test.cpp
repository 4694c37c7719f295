#include "scene/mesh_ops.h"

#include <glm/gtc/constants.hpp>
#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace glint {
namespace {

// A latitude-longitude sphere of radius 2 around `center`, counter-clockwise from outside, with
// vertices shared between neighbouring triangles (one vertex per pole).
Mesh make_sphere(vec3 center, int rings = 12, int segments = 24) {
  Mesh mesh;
  mesh.name = "sphere";
  constexpr float kRadius = 2.0f;
  mesh.positions.push_back(center + vec3(0.0f, kRadius, 0.0f));  // north pole: 0
  for (int ring = 1; ring < rings; ++ring) {
    const float polar = glm::pi<float>() * static_cast<float>(ring) / static_cast<float>(rings);
    for (int s = 0; s < segments; ++s) {
      const float azimuth = glm::two_pi<float>() * static_cast<float>(s) / static_cast<float>(segments);
      mesh.positions.push_back(center + kRadius * vec3(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                                                       -std::sin(polar) * std::sin(azimuth)));
    }
  }
  const auto south = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.push_back(center - vec3(0.0f, kRadius, 0.0f));
  auto at = [&](int ring, int s) { return static_cast<std::uint32_t>(1 + (ring - 1) * segments + (s % segments)); };
  for (int s = 0; s < segments; ++s) {
    mesh.indices.insert(mesh.indices.end(), {0u, at(1, s), at(1, s + 1)});
    mesh.indices.insert(mesh.indices.end(), {south, at(rings - 1, s + 1), at(rings - 1, s)});
    for (int ring = 1; ring + 1 < rings; ++ring)
      mesh.indices.insert(mesh.indices.end(), {at(ring, s), at(ring + 1, s), at(ring + 1, s + 1), at(ring, s),
                                               at(ring + 1, s + 1), at(ring, s + 1)});
  }
  return mesh;
}

vec3 face_normal(const Mesh& mesh, std::size_t triangle) {
  const vec3 a = mesh.positions[mesh.indices[3 * triangle]], b = mesh.positions[mesh.indices[3 * triangle + 1]],
             c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return glm::normalize(glm::cross(b - a, c - a));
}

TEST(MeshOps, SphereIsBuiltOutwardFacing) {
  // Guards the fixture the other tests rely on.
  const Mesh sphere = make_sphere(vec3(0.0f));
  for (std::size_t t = 0; t < sphere.triangle_count(); ++t) {
    const vec3 centroid = (sphere.positions[sphere.indices[3 * t]] + sphere.positions[sphere.indices[3 * t + 1]] +
                           sphere.positions[sphere.indices[3 * t + 2]]) / 3.0f;
    ASSERT_GT(glm::dot(face_normal(sphere, t), centroid), 0.0f) << "triangle " << t;
  }
}

TEST(MeshOps, SmoothNormalsOfASpherePointRadially) {
  const vec3 center(3.0f, -1.0f, 0.5f);
  Mesh sphere = make_sphere(center);
  compute_smooth_normals(sphere);
  ASSERT_EQ(sphere.normals.size(), sphere.positions.size());
  for (std::size_t v = 0; v < sphere.vertex_count(); ++v) {
    EXPECT_NEAR(glm::length(sphere.normals[v]), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(sphere.normals[v], glm::normalize(sphere.positions[v] - center)), 0.995f) << "vertex " << v;
  }
}

TEST(MeshOps, SmoothNormalsAreAreaWeighted) {
  // Vertex 0 is shared by a large triangle with normal +z and a small one with normal +x: the
  // result leans towards +z by the ratio of the areas (8 : 0.5).
  Mesh mesh;
  mesh.positions = {vec3(0, 0, 0), vec3(4, 0, 0), vec3(0, 4, 0), vec3(0, 1, 0), vec3(0, 0, 1)};
  mesh.indices = {0, 1, 2, 0, 3, 4};
  compute_smooth_normals(mesh);
  EXPECT_NEAR(mesh.normals[0].z / mesh.normals[0].x, 16.0f, 1e-4f);
  EXPECT_EQ(mesh.normals[1], vec3(0, 0, 1));
}

TEST(MeshOps, VertexOnNoFaceGetsUp) {
  Mesh mesh;
  mesh.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 0, -1), vec3(5, 5, 5)};
  mesh.indices = {0, 1, 2};
  compute_smooth_normals(mesh);
  EXPECT_EQ(mesh.normals[3], vec3(0, 1, 0));
  EXPECT_EQ(mesh.normals[0], vec3(0, 1, 0));  // the triangle faces +y too
}

TEST(MeshOps, FlatNormalsGiveEachTriangleItsOwnVertices) {
  Mesh sphere = make_sphere(vec3(0.0f), 6, 8);
  sphere.uvs.resize(sphere.positions.size());
  for (std::size_t v = 0; v < sphere.uvs.size(); ++v) sphere.uvs[v] = vec2(static_cast<float>(v), 0.5f);
  const Mesh before = sphere;
  compute_flat_normals(sphere);
  ASSERT_EQ(sphere.triangle_count(), before.triangle_count());
  ASSERT_EQ(sphere.vertex_count(), 3 * before.triangle_count());
  ASSERT_EQ(sphere.normals.size(), sphere.vertex_count());
  ASSERT_EQ(sphere.uvs.size(), sphere.vertex_count());
  for (std::size_t i = 0; i < sphere.indices.size(); ++i) {
    EXPECT_EQ(sphere.indices[i], i);  // no sharing
    // Same corner positions and UVs as before, in the same order.
    EXPECT_EQ(sphere.positions[i], before.positions[before.indices[i]]);
    EXPECT_EQ(sphere.uvs[i], before.uvs[before.indices[i]]);
    const vec3 expected = face_normal(before, i / 3);
    EXPECT_NEAR(glm::distance(sphere.normals[i], expected), 0.0f, 1e-6f) << "corner " << i;
  }
}

TEST(MeshOps, FlatNormalsKeepUvsEmptyWhenThereAreNone) {
  Mesh sphere = make_sphere(vec3(0.0f), 4, 6);
  compute_flat_normals(sphere);
  EXPECT_TRUE(sphere.uvs.empty());
}

TEST(MeshOps, DegenerateTrianglesAreRemovedAndCounted) {
  Mesh mesh;
  mesh.positions = {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0), vec3(2, 0, 0), vec3(1, 1, 0), vec3(0, 0, 0)};
  mesh.indices = {0, 1, 2,   // kept
                  0, 0, 1,   // repeated index
                  0, 1, 3,   // collinear
                  1, 4, 2,   // kept
                  0, 5, 1};  // two distinct vertices at the same place
  EXPECT_EQ(remove_degenerate_triangles(mesh), 3u);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 4, 2}));  // survivors, in order
  EXPECT_EQ(mesh.positions.size(), 6u);  // vertices are kept
  EXPECT_EQ(remove_degenerate_triangles(mesh), 0u);
}

TEST(MeshOps, DegeneracyIsRelativeToTheTriangleSize) {
  // A well-shaped triangle a micrometre across is fine; a sliver whose apex is 1e-7 of its length
  // off the line is not.
  EXPECT_FALSE(is_degenerate_triangle(vec3(0.0f), vec3(1e-6f, 0, 0), vec3(0, 1e-6f, 0)));
  EXPECT_FALSE(is_degenerate_triangle(vec3(0.0f), vec3(1e4f, 0, 0), vec3(0, 1e4f, 0)));
  EXPECT_TRUE(is_degenerate_triangle(vec3(0.0f), vec3(1, 0, 0), vec3(0.5f, 1e-7f, 0)));
  EXPECT_TRUE(is_degenerate_triangle(vec3(1.0f), vec3(1.0f), vec3(1.0f)));
}

TEST(MeshOps, HugeAndTinyValidTrianglesAreNotDegenerate) {
  // Legs of 5e9: |e1|^2 |e2|^2 = 6.25e38 overflowed float, and the triangle was dropped as "zero-area".
  EXPECT_FALSE(is_degenerate_triangle(vec3(0.0f), vec3(5e9f, 0, 0), vec3(0, 5e9f, 0)));
  EXPECT_FALSE(is_degenerate_triangle(vec3(0.0f), vec3(1e30f, 0, 0), vec3(0, 1e30f, 0)));
  // Legs of 1e-12: the same product underflowed to 0 in float.
  EXPECT_FALSE(is_degenerate_triangle(vec3(0.0f), vec3(1e-12f, 0, 0), vec3(0, 1e-12f, 0)));
  // Their normals survive too (the cross product's length overflowed from legs of about 1e9).
  Mesh mesh;
  mesh.positions = {vec3(0.0f), vec3(5e9f, 0, 0), vec3(0, 5e9f, 0)};
  mesh.indices = {0, 1, 2};
  EXPECT_EQ(remove_degenerate_triangles(mesh), 0u);
  compute_smooth_normals(mesh);
  EXPECT_NEAR(mesh.normals[0].z, 1.0f, 1e-6f);
  compute_flat_normals(mesh);
  EXPECT_NEAR(mesh.normals[0].z, 1.0f, 1e-6f);
}

TEST(MeshOps, ScalingAMeshDoesNotChangeWhichTrianglesAreDegenerate) {
  // Well-shaped, thin but valid (apex 1e-5 of the length off the line), slivers (1e-7) and a
  // repeated point, at scales from 1e-12 to 1e12 (a scene in km or in micrometres): the same verdicts.
  const std::vector<std::array<vec3, 3>> triangles = {
      {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0, 1, 0)},      {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0.5f, 1e-5f, 0)},
      {vec3(0, 0, 0), vec3(1, 0, 0), vec3(0.5f, 1e-7f, 0)}, {vec3(0.3f, 0.2f, 0.1f), vec3(0.3f, 0.2f, 0.1f), vec3(1, 1, 1)},
      {vec3(1, 2, 3), vec3(4, -5, 6), vec3(-7, 8, 9)}};
  const std::vector<bool> expected = {false, false, true, true, false};
  for (const float scale : {1e-12f, 1e-3f, 1.0f, 1e3f, 5e9f, 1e12f})
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const auto& [a, b, c] = triangles[t];
      EXPECT_EQ(is_degenerate_triangle(a * scale, b * scale, c * scale), expected[t]) << "triangle " << t << " x " << scale;
    }
}

}  // namespace
}  // namespace glint
