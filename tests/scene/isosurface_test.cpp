#include "scene/procedural/isosurface.h"

#include "core/error.h"

#include "scene/mesh_checks.h"
#include "scene/mesh_ops.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint::procedural {
namespace {

constexpr float kRadius = 0.8f;
float sphere(const vec3& p) { return glm::length(p - vec3(0.1f, -0.2f, 0.05f)) - kRadius; }
Aabb sphere_bounds() {
  Aabb box;
  box.extend(vec3(0.1f, -0.2f, 0.05f) - vec3(kRadius));
  box.extend(vec3(0.1f, -0.2f, 0.05f) + vec3(kRadius));
  return box;
}

TEST(Isosurface, SphereIsClosedGenusZeroAndOnTheSurface) {
  const float cell = 0.05f;
  const Mesh mesh = polygonize(sphere, sphere_bounds(), cell);
  ASSERT_GT(mesh.vertex_count(), 1000u);
  const testing::EdgeReport edges = testing::edge_report(mesh);
  EXPECT_EQ(edges.not_shared_by_two, 0u);
  EXPECT_EQ(edges.inconsistent, 0u);
  EXPECT_EQ(testing::euler_characteristic(mesh), 2);
  // Closed genus-0 triangle mesh: F = 2V - 4.
  EXPECT_EQ(mesh.triangle_count(), 2 * mesh.vertex_count() - 4);
  const vec3 centre(0.1f, -0.2f, 0.05f);
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const vec3 radial = mesh.positions[v] - centre;
    ASSERT_NEAR(glm::length(radial), kRadius, 0.2f * cell) << "vertex " << v;
    ASSERT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-4f);
    ASSERT_GT(glm::dot(mesh.normals[v], glm::normalize(radial)), 0.9f) << "vertex " << v;
  }
  EXPECT_GT(testing::signed_volume(mesh), 0.0);
  const double exact = 4.0 / 3.0 * 3.14159265358979 * kRadius * kRadius * kRadius;
  EXPECT_NEAR(testing::signed_volume(mesh), exact, 0.03 * exact);
  EXPECT_EQ(testing::fraction_winding_matches_normals(mesh), 1.0);
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3)
    ASSERT_FALSE(is_degenerate_triangle(mesh.positions[mesh.indices[t]], mesh.positions[mesh.indices[t + 1]],
                                        mesh.positions[mesh.indices[t + 2]]));
}

TEST(Isosurface, VertexCountGrowsWithTheSquareOfTheResolution) {
  const std::size_t coarse = polygonize(sphere, sphere_bounds(), 0.08f).vertex_count();
  const std::size_t fine = polygonize(sphere, sphere_bounds(), 0.04f).vertex_count();
  EXPECT_EQ(count_surface_vertices(sphere, sphere_bounds(), 0.04f), fine);
  const double ratio = static_cast<double>(fine) / static_cast<double>(coarse);
  EXPECT_GT(ratio, 3.6);
  EXPECT_LT(ratio, 4.4);
}

TEST(Isosurface, TwoSeparateSpheresGiveTwoComponents) {
  const auto field = [](const vec3& p) {
    return std::min(glm::length(p - vec3(-1, 0, 0)) - 0.5f, glm::length(p - vec3(1, 0, 0)) - 0.5f);
  };
  Aabb box;
  box.extend(vec3(-1.5f, -0.5f, -0.5f));
  box.extend(vec3(1.5f, 0.5f, 0.5f));
  const Mesh mesh = polygonize(field, box, 0.05f);
  EXPECT_EQ(testing::edge_report(mesh).not_shared_by_two, 0u);
  EXPECT_EQ(testing::euler_characteristic(mesh), 4);  // two spheres
}

TEST(Isosurface, TargetSearchLandsWithinTolerance) {
  for (const std::size_t target : {3000u, 20000u}) {
    const TargetedMesh result = polygonize_to_vertex_count(sphere, sphere_bounds(), target, 0.01f);
    const double error = std::abs(static_cast<double>(result.mesh.vertex_count()) - static_cast<double>(target)) /
                         static_cast<double>(target);
    EXPECT_LE(error, 0.01) << "target " << target << " got " << result.mesh.vertex_count();
    EXPECT_GT(result.cell_size, 0.0f);
    EXPECT_LE(result.meshes_built, 5);
    // Deterministic: the same search gives the same mesh.
    const TargetedMesh again = polygonize_to_vertex_count(sphere, sphere_bounds(), target, 0.01f);
    EXPECT_EQ(again.mesh.positions, result.mesh.positions);
    EXPECT_EQ(again.mesh.indices, result.mesh.indices);
  }
}

TEST(Isosurface, RejectsInvalidCellSize) {
  EXPECT_THROW(polygonize(sphere, sphere_bounds(), 0.0f), Error);
  EXPECT_THROW(polygonize_to_vertex_count(sphere, sphere_bounds(), 2), Error);
}

}  // namespace
}  // namespace glint::procedural
