// ShadowCubePass: the per-face and layered draws give the same cube map, texel for texel, and the
// depths are distances to the light over the far distance (checked where the geometry is known).
#include "gl/gl_test_context.h"
#include "raster_test_scene.h"
#include "render/gpu_scene.h"
#include "render/raster_settings.h"
#include "render/shadow_cube_pass.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace glint {
namespace {

using render::ShadowCubeDraw;
using render::ShadowCubePass;
using ShadowCube = testing::GlTest;

constexpr int kFaceSize = 64;

// All six faces, GL face order (+X, -X, +Y, -Y, +Z, -Z), each kFaceSize^2 depths row by row.
std::vector<float> read_cube(const ShadowCubePass& pass) {
  std::vector<float> depths(6 * std::size_t{kFaceSize} * kFaceSize);
  glGetTextureImage(pass.cube_map(), 0, GL_DEPTH_COMPONENT, GL_FLOAT, static_cast<GLsizei>(depths.size() * sizeof(float)),
                    depths.data());
  return depths;
}

float texel(const std::vector<float>& cube, int face, int x, int y) {
  return cube[(static_cast<std::size_t>(face) * kFaceSize + static_cast<std::size_t>(y)) * kFaceSize +
              static_cast<std::size_t>(x)];
}

// The instances' world boxes, for the per-face draw's culling.
std::vector<std::optional<Aabb>> instance_boxes(const Scene& scene) {
  std::vector<std::optional<Aabb>> boxes;
  for (const Instance& instance : scene.instances)
    boxes.push_back(transform_aabb(instance.transform, scene.meshes[instance.mesh].bounds()));
  return boxes;
}

TEST_F(ShadowCube, PerFaceAndLayeredDrawsGiveTheSameDepths) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  const render::GpuScene gpu(scene);
  // The scene's light, then one off-centre so that triangles straddle several faces.
  for (const vec3 light : {scene.light.position, vec3(1.7f, 1.2f, -0.4f)}) {
    ShadowCubePass per_face(kFaceSize, ShadowCubeDraw::per_face);
    ShadowCubePass layered(kFaceSize, ShadowCubeDraw::layered);
    per_face.run(gpu, light, scene.world_bounds(), instance_boxes(scene));
    layered.run(gpu, light, scene.world_bounds());
    ASSERT_EQ(per_face.far_distance(), layered.far_distance());
    const std::vector<float> a = read_cube(per_face), b = read_cube(layered);
    size_t differing = 0, covered = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      differing += a[i] != b[i];
      covered += a[i] < 1.0f;
    }
    EXPECT_EQ(differing, 0u) << "light " << light.x << " " << light.y << " " << light.z;
    EXPECT_GT(covered, a.size() / 4) << "the floor alone covers the lower half of the cube";
  }
}

TEST_F(ShadowCube, CullingInstancesPerFaceChangesNoDepth) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);  // floor, lid, wall: 3 instances
  const render::GpuScene gpu(scene);
  std::vector<std::optional<Aabb>> boxes = instance_boxes(scene);
  const vec3 light = scene.light.position;  // (0, 4, 0), above the lid (y = 2) and the wall (y <= 1)
  ShadowCubePass culled(kFaceSize, ShadowCubeDraw::per_face), reference(kFaceSize, ShadowCubeDraw::layered);
  culled.run(gpu, light, scene.world_bounds(), boxes);
  reference.run(gpu, light, scene.world_bounds());
  EXPECT_EQ(read_cube(culled), read_cube(reference));
  // Nothing reaches above the light: +Y (face 2) draws nothing; -Y (face 3) sees all three.
  EXPECT_EQ(culled.face_instance_counts()[2], 0u);
  EXPECT_EQ(culled.face_instance_counts()[3], 3u);
  // An instance without a box (one that deforms) is drawn into every face.
  boxes[1] = std::nullopt;
  culled.run(gpu, light, scene.world_bounds(), boxes);
  EXPECT_EQ(culled.face_instance_counts()[2], 1u);
  EXPECT_EQ(read_cube(culled), read_cube(reference));
  EXPECT_THROW(culled.run(gpu, light, scene.world_bounds(), std::span(boxes).first(2)), Error);
}

TEST_F(ShadowCube, DepthIsTheDistanceToTheLightOverFar) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  const render::GpuScene gpu(scene);
  const vec3 light = scene.light.position;  // (0, 4, 0): the lid (y = 2) is straight below it
  for (const ShadowCubeDraw draw : {ShadowCubeDraw::per_face, ShadowCubeDraw::layered}) {
    ShadowCubePass pass(kFaceSize, draw);
    pass.run(gpu, light, scene.world_bounds());
    const std::vector<float> cube = read_cube(pass);
    // -Y (face 3), centre: the lid, 2 below the light (texel centres are within half a texel of
    // straight down: 1 / cos of that angle is 1 + 2e-4).
    EXPECT_NEAR(texel(cube, 3, kFaceSize / 2, kFaceSize / 2) * pass.far_distance(), 2.0f, 2e-3f);
    // +Y (face 2): nothing above the light.
    for (int y = 0; y < kFaceSize; ++y)
      for (int x = 0; x < kFaceSize; ++x) ASSERT_EQ(texel(cube, 2, x, y), 1.0f) << x << ", " << y;
  }
  EXPECT_EQ(render::parse_shadow_cube_draw("layered"), ShadowCubeDraw::layered);
  EXPECT_EQ(render::parse_shadow_cube_draw(render::shadow_cube_draw_name(ShadowCubeDraw::per_face)),
            ShadowCubeDraw::per_face);
  EXPECT_THROW(render::parse_shadow_cube_draw("geometry"), Error);
}

}  // namespace
}  // namespace glint
