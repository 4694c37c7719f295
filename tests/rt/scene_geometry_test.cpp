#include "rt/scene_geometry.h"

#include "rt/tiny_scene.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::rt {
namespace {

vec3 world(const Scene& scene, uint32_t instance, vec3 local) {
  return vec3(scene.instances[instance].transform * vec4(local, 1.0f));
}

TEST(SceneGeometry, EveryWorldTriangleIsItsSourceTriangleTransformed) {
  const Scene scene = testing::make_tiny_scene(4);
  const SceneGeometry geometry = flatten_scene(scene);
  ASSERT_EQ(geometry.triangle_count(), scene.triangle_count());
  ASSERT_EQ(geometry.positions.size(), scene.vertex_count());
  ASSERT_EQ(geometry.instances.size(), 4u);
  const accel::TriangleMesh mesh = geometry.mesh();
  for (uint32_t t = 0; t < geometry.triangle_count(); ++t) {
    const TriangleSource& source = geometry.sources[t];
    const Mesh& local = scene.meshes[source.mesh];
    EXPECT_EQ(scene.instances[source.instance].mesh, source.mesh);
    const accel::Triangle tri = mesh.triangle(t);
    const vec3 corners[3] = {tri.v0, tri.v1, tri.v2};
    for (int k = 0; k < 3; ++k) {
      const vec3 expected = world(scene, source.instance, local.positions[local.indices[3 * source.local_triangle + k]]);
      EXPECT_LT(glm::length(corners[k] - expected), 1e-5f) << "triangle " << t << " corner " << k;
    }
  }
  // The rotated sheet really is rotated: its local x axis points along world -z.
  const InstanceRange& b = geometry.instances[3];
  EXPECT_EQ(b.instance, 3u);
  const vec3 p0 = geometry.positions[b.first_vertex], p1 = geometry.positions[b.first_vertex + 1];
  EXPECT_NEAR(p1.z - p0.z, -0.25f, 1e-5f);
  EXPECT_NEAR(p1.x - p0.x, 0.0f, 1e-5f);
}

TEST(SceneGeometry, DeformableRangesCoverExactlyTheDeformableInstances) {
  const Scene scene = testing::make_tiny_scene(4);
  const SceneGeometry geometry = flatten_scene(scene);
  ASSERT_EQ(geometry.deformable.size(), 2u);
  for (const InstanceRange& range : geometry.deformable) {
    EXPECT_EQ(range.mesh, 2u);
    EXPECT_EQ(range.triangle_count, 32u);
    for (uint32_t t = range.first_triangle; t < range.first_triangle + range.triangle_count; ++t)
      EXPECT_EQ(geometry.sources[t].instance, range.instance);
  }
  const std::vector<uint32_t> deformable = scene.deformable_meshes();
  const SceneGeometry only = flatten_scene(scene, deformable);
  EXPECT_EQ(only.triangle_count(), 64u);
  EXPECT_EQ(only.instances.size(), 2u);
  EXPECT_EQ(only.sources.front().instance, 2u);
  const std::vector<uint32_t> bad{7};
  EXPECT_NE(glint::testing::error_of([&] { (void)flatten_scene(scene, bad); }).find("mesh index 7"), std::string::npos);
}

TEST(SceneGeometry, UpdateDeformedEqualsAFreshFlattenAndTouchesOnlyDirtyMeshes) {
  Scene scene = testing::make_tiny_scene(6);
  SceneGeometry geometry = flatten_scene(scene);
  const SceneGeometry rest = geometry;
  SceneDeformers deformers(scene);
  const std::vector<uint32_t> dirty = deformers.apply(scene, 17);
  ASSERT_EQ(dirty, std::vector<uint32_t>{2});
  update_deformed(geometry, scene, dirty);
  const SceneGeometry fresh = flatten_scene(scene);
  EXPECT_EQ(geometry.positions, fresh.positions);
  EXPECT_EQ(geometry.indices, rest.indices);
  // The sheets did move, the floor and wall did not.
  EXPECT_NE(geometry.positions, rest.positions);
  for (const InstanceRange& range : geometry.instances) {
    if (range.mesh == 2) continue;
    for (uint32_t v = range.first_vertex; v < range.first_vertex + range.vertex_count; ++v)
      EXPECT_EQ(geometry.positions[v], rest.positions[v]);
  }

  Scene changed = scene;
  changed.meshes[2].positions.pop_back();
  EXPECT_NE(glint::testing::error_of([&] { update_deformed(geometry, changed, dirty); }).find("'sheet'"),
            std::string::npos);
}

TEST(SceneGeometry, InvalidSceneIsAnError) {
  Scene scene = testing::make_tiny_scene(2);
  scene.instances.clear();
  EXPECT_THROW((void)flatten_scene(scene), Error);
}

}  // namespace
}  // namespace glint::rt
