#include "scene/sine_deformer.h"

#include "core/error.h"
#include "scene/mesh_ops.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

// An n x n vertex grid in the xz plane (y = 0) over [0, size]^2 with UVs, two triangles per cell.
Mesh grid(int n, float size, const std::string& name = "grid") {
  Mesh mesh;
  mesh.name = name;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(n - 1), v = static_cast<float>(j) / static_cast<float>(n - 1);
      mesh.positions.emplace_back(u * size, 0.0f, v * size);
      mesh.uvs.emplace_back(u, v);
    }
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const auto a = static_cast<std::uint32_t>(j * n + i), b = a + 1, c = a + static_cast<std::uint32_t>(n), d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});  // counter-clockwise seen from +y
    }
  compute_smooth_normals(mesh);
  return mesh;
}

SineDeform wave() {
  SineDeform p;
  p.displace_axis = 1;
  p.wave_axis = 0;
  p.amplitude = 0.3f;
  p.frequency = 2.5f;
  p.speed = 1.7f;
  return p;
}

TEST(SineDeformer, MovesEveryVertexByTheSineFormula) {
  // 40 000 vertices: above the parallel grain, so the TBB path runs.
  const Mesh rest = grid(200, 6.0f);
  Mesh mesh = rest;
  const SineDeform p = wave();
  const float t = 2.25f;
  SineDeformer(rest, p).apply(mesh, t);
  double worst = 0.0;
  for (std::size_t v = 0; v < rest.vertex_count(); ++v) {
    const glm::dvec3 r(rest.positions[v]);
    const double expected_y = r.y + double(p.amplitude) * std::sin(double(p.frequency) * r.x + double(p.speed) * t);
    worst = std::max(worst, std::abs(double(mesh.positions[v].y) - expected_y));
    ASSERT_EQ(mesh.positions[v].x, rest.positions[v].x) << v;  // only the displace axis moves
    ASSERT_EQ(mesh.positions[v].z, rest.positions[v].z) << v;
  }
  EXPECT_LT(worst, 2e-6);
  EXPECT_GT(std::abs(mesh.positions[1234].y), 1e-3f);  // and it did move
}

TEST(SineDeformer, UsesTheConfiguredAxes) {
  const Mesh rest = grid(8, 2.0f);
  Mesh mesh = rest;
  SineDeform p = wave();
  p.displace_axis = 0;  // x moves, waving along z
  p.wave_axis = 2;
  SineDeformer(rest, p).apply(mesh, 0.5f);
  for (std::size_t v : {std::size_t{0}, std::size_t{9}, std::size_t{37}, std::size_t{63}}) {
    const vec3 r = rest.positions[v];
    EXPECT_NEAR(mesh.positions[v].x, r.x + p.amplitude * std::sin(p.frequency * r.z + p.speed * 0.5f), 1e-6f) << v;
    EXPECT_EQ(mesh.positions[v].y, r.y);
    EXPECT_EQ(mesh.positions[v].z, r.z);
  }
}

TEST(SineDeformer, KeepsTrianglesIndicesAndUvs) {
  const Mesh rest = grid(30, 3.0f);
  Mesh mesh = rest;
  SineDeformer(rest, wave()).apply(mesh, 1.0f);
  EXPECT_EQ(mesh.triangle_count(), rest.triangle_count());
  EXPECT_EQ(mesh.indices, rest.indices);
  EXPECT_EQ(mesh.uvs, rest.uvs);
  EXPECT_EQ(mesh.vertex_count(), rest.vertex_count());
  EXPECT_EQ(mesh.normals.size(), rest.vertex_count());
}

TEST(SineDeformer, IsDeterministicForAGivenTime) {
  const Mesh rest = grid(120, 4.0f);
  SineDeformer deformer(rest, wave());
  Mesh mesh = rest;
  deformer.apply(mesh, 0.75f);
  const Mesh first = mesh;
  deformer.apply(mesh, 3.5f);
  ASSERT_NE(mesh.positions, first.positions);
  deformer.apply(mesh, 0.75f);
  EXPECT_EQ(mesh.positions, first.positions);  // bit-identical: computed from the rest pose
  EXPECT_EQ(mesh.normals, first.normals);
}

TEST(SineDeformer, NormalsAreUnitAndEqualAFreshSmoothNormalComputation) {
  const Mesh rest = grid(150, 5.0f);  // 22 500 vertices: the parallel gather runs
  Mesh mesh = rest;
  SineDeformer(rest, wave()).apply(mesh, 1.3f);
  Mesh reference = mesh;
  compute_smooth_normals(reference);
  int tilted = 0;
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    ASSERT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-5f) << v;
    ASSERT_LT(glm::distance(mesh.normals[v], reference.normals[v]), 1e-6f) << v;
    if (mesh.normals[v].y < 0.99f) ++tilted;
  }
  EXPECT_GT(tilted, 1000);  // the wave really bends the normals away from the flat grid's +y
}

TEST(SineDeformer, ZeroAmplitudeLeavesTheMeshUnchanged) {
  const Mesh rest = grid(20, 2.0f);
  Mesh mesh = rest;
  SineDeform p = wave();
  p.amplitude = 0.0f;
  SineDeformer(rest, p).apply(mesh, 4.0f);
  EXPECT_EQ(mesh.positions, rest.positions);
  EXPECT_EQ(mesh.normals, rest.normals);
}

TEST(SineDeformer, RejectsAMismatchedMeshAndBadParameters) {
  const Mesh rest = grid(10, 1.0f);
  SineDeformer deformer(rest, wave());
  Mesh other = grid(11, 1.0f);
  EXPECT_THROW(deformer.apply(other, 0.0f), Error);
  Mesh fewer_triangles = rest;
  fewer_triangles.indices.resize(fewer_triangles.indices.size() - 3);
  EXPECT_THROW(deformer.apply(fewer_triangles, 0.0f), Error);
  SineDeform bad_axis = wave();
  bad_axis.displace_axis = 3;
  EXPECT_THROW(SineDeformer(rest, bad_axis), Error);
  SineDeform bad_wave = wave();
  bad_wave.wave_axis = -1;
  EXPECT_THROW(SineDeformer(rest, bad_wave), Error);
  SineDeform bad_speed = wave();
  bad_speed.speed = std::numeric_limits<float>::infinity();
  EXPECT_THROW(SineDeformer(rest, bad_speed), Error);
  Mesh bad_index = rest;
  bad_index.indices[4] = 1000;
  EXPECT_THROW(SineDeformer(bad_index, wave()), Error);
}

// SceneDeformers lives in this suite so that the module's test filter (SineDeform*) runs it.
TEST(SineDeformScene, DeformsExactlyTheDeformableMeshesAtFrameOverFps) {
  Scene scene;
  scene.meshes.push_back(grid(12, 2.0f, "static"));
  scene.meshes.push_back(grid(12, 2.0f, "waving"));
  scene.meshes.back().deformable = true;
  scene.meshes.back().deform = wave();
  scene.meshes.push_back(grid(12, 2.0f, "deformable without parameters"));
  scene.meshes.back().deformable = true;
  scene.meshes.push_back(grid(12, 2.0f, "parameters but not deformable"));
  scene.meshes.back().deform = wave();
  scene.meshes.push_back(grid(9, 1.0f, "second waving"));
  scene.meshes.back().deformable = true;
  scene.meshes.back().deform = wave();
  scene.walkthrough.frames_per_second = 30.0f;
  const Scene rest = scene;

  SceneDeformers deformers(scene);
  EXPECT_EQ(deformers.meshes(), (std::vector<std::uint32_t>{1, 4}));
  const std::vector<std::uint32_t> dirty = deformers.apply(scene, 45);  // t = 1.5 s
  EXPECT_EQ(dirty, (std::vector<std::uint32_t>{1, 4}));
  for (std::uint32_t m : {0u, 2u, 3u}) {
    EXPECT_EQ(scene.meshes[m].positions, rest.meshes[m].positions) << m;
    EXPECT_EQ(scene.meshes[m].normals, rest.meshes[m].normals) << m;
  }
  for (std::uint32_t m : {1u, 4u}) {
    Mesh expected = rest.meshes[m];
    SineDeformer(rest.meshes[m], wave()).apply(expected, 1.5f);
    EXPECT_EQ(scene.meshes[m].positions, expected.positions) << m;
    EXPECT_EQ(scene.meshes[m].normals, expected.normals) << m;
  }
}

TEST(SineDeformScene, RejectsBadFramesAndScenes) {
  Scene scene;
  scene.meshes.push_back(grid(4, 1.0f));
  scene.meshes.back().deformable = true;
  scene.meshes.back().deform = wave();
  SceneDeformers deformers(scene);
  EXPECT_THROW((void)deformers.apply(scene, -1), Error);
  Scene bigger = scene;
  bigger.meshes.push_back(grid(4, 1.0f));
  EXPECT_THROW((void)deformers.apply(bigger, 0), Error);
  scene.walkthrough.frames_per_second = 0.0f;
  EXPECT_THROW(SceneDeformers{scene}, Error);

  Scene none;
  none.meshes.push_back(grid(4, 1.0f));
  SceneDeformers nothing(none);
  EXPECT_TRUE(nothing.empty());
  EXPECT_TRUE(nothing.apply(none, 10).empty());
}

}  // namespace
}  // namespace glint
