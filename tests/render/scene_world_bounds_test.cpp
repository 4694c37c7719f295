// SceneWorldBounds: the frame's world bounds without scanning every vertex every frame, equal to
// Scene::world_bounds() bit for bit while the host's vertices and the GPU's agree: after a deformable
// mesh moved (rescanned every frame), after a static mesh's vertices were replaced through
// GpuScene::update_mesh_vertices (rescanned once), after an instance moved, and on a scene scaled by
// 1000 and moved far from the origin; a static mesh whose vertices nobody uploaded keeps its box.
#include "raster_test_scene.h"
#include "render/gpu_scene.h"
#include "render/scene_world_bounds.h"
#include "../gl/gl_test_context.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace glint::render {
namespace {

using SceneWorldBoundsTest = testing::GlTest;

void expect_same(const Aabb& a, const Aabb& b) {
  EXPECT_EQ(a.min, b.min);
  EXPECT_EQ(a.max, b.max);
}

struct TwoQuads {
  Scene scene;
  std::uint32_t still = 0, deforming = 0;
};

TwoQuads two_quads(float scale, vec3 offset) {
  TwoQuads s{testing::make_empty_test_scene(offset + vec3(0.0f, 5.0f, 0.0f) * scale)};
  const std::uint32_t grey = testing::add_material(s.scene, vec3(0.5f));
  s.still = testing::add_quad(s.scene, offset + vec3(-1.0f, 0.0f, -8.0f) * scale, vec3(2.0f, 0.0f, 0.0f) * scale,
                              vec3(0.0f, 1.0f, 0.0f) * scale, grey);
  s.deforming = testing::add_quad(s.scene, offset + vec3(-2.0f, 0.0f, -5.0f) * scale, vec3(4.0f, 0.0f, 0.0f) * scale,
                                  vec3(0.0f, 4.0f, 0.0f) * scale, grey);
  s.scene.meshes[s.deforming].deformable = true;
  s.scene.meshes[s.deforming].deform = SineDeform{};
  return s;
}

TEST_F(SceneWorldBoundsTest, EqualsTheFullScanAsMeshesAndInstancesMove) {
  for (const auto& [scale, offset] : {std::pair{1.0f, vec3(0.0f)}, std::pair{1000.0f, vec3(1e4f, -2e4f, 3e4f)}}) {
    SCOPED_TRACE(scale);
    TwoQuads s = two_quads(scale, offset);
    GpuScene gpu(s.scene);
    SceneWorldBounds bounds;
    expect_same(bounds.of(s.scene, gpu), s.scene.world_bounds());

    // A deformable mesh's host vertices move every frame (the CPU deformer writes them): seen at once.
    for (vec3& p : s.scene.meshes[s.deforming].positions) p.y += 7.0f * scale;
    expect_same(bounds.of(s.scene, gpu), s.scene.world_bounds());

    // A static mesh replaced on both sides: seen at the next frame.
    std::vector<vec3>& still = s.scene.meshes[s.still].positions;
    for (vec3& p : still) p.z -= 30.0f * scale;
    gpu.update_mesh_vertices(s.still, still, s.scene.meshes[s.still].normals);
    expect_same(bounds.of(s.scene, gpu), s.scene.world_bounds());

    // An instance moved.
    s.scene.instances[s.still].transform = glm::translate(mat4(1.0f), vec3(0.0f, -50.0f, 0.0f) * scale);
    expect_same(bounds.of(s.scene, gpu), s.scene.world_bounds());
  }
}

TEST_F(SceneWorldBoundsTest, StaticMeshIsNotScannedAgainUntilItsVerticesAreUploaded) {
  TwoQuads s = two_quads(1.0f, vec3(0.0f));
  GpuScene gpu(s.scene);
  SceneWorldBounds bounds;
  const Aabb before = bounds.of(s.scene, gpu);
  // Host vertices changed but never uploaded: the GPU still draws the old ones, and so do the bounds.
  for (vec3& p : s.scene.meshes[s.still].positions) p.x -= 100.0f;
  expect_same(bounds.of(s.scene, gpu), before);
  EXPECT_LT(s.scene.world_bounds().min.x, before.min.x - 50.0f);
  gpu.update_mesh_vertices(s.still, s.scene.meshes[s.still].positions, s.scene.meshes[s.still].normals);
  expect_same(bounds.of(s.scene, gpu), s.scene.world_bounds());
}

}  // namespace
}  // namespace glint::render
