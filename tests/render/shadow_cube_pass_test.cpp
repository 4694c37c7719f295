// ShadowCubePass: the per-face and layered draws give the same cube map, texel for texel, and the
// depths are near / (distance along the face's axis), checked where the geometry is known.
#include "gl/gl_test_context.h"
#include "raster_test_scene.h"
#include "render/gpu_scene.h"
#include "render/raster_settings.h"
#include "render/shadow_chunks.h"
#include "render/shadow_cube_pass.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
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

TEST_F(ShadowCube, PerFaceAndLayeredDrawsGiveTheSameDepths) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  const render::GpuScene gpu(scene);
  // The scene's light, then one off-centre so that triangles straddle several faces.
  for (const vec3 light : {scene.light.position, vec3(1.7f, 1.2f, -0.4f)}) {
    ShadowCubePass per_face(kFaceSize, ShadowCubeDraw::per_face);
    ShadowCubePass layered(kFaceSize, ShadowCubeDraw::layered);
    per_face.run(gpu, light, scene.world_bounds());
    layered.run(gpu, light, scene.world_bounds());
    ASSERT_EQ(per_face.near_distance(), layered.near_distance());
    const std::vector<float> a = read_cube(per_face), b = read_cube(layered);
    size_t differing = 0, covered = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      differing += a[i] != b[i];
      covered += a[i] > 0.0f;
    }
    EXPECT_EQ(differing, 0u) << "light " << light.x << " " << light.y << " " << light.z;
    EXPECT_GT(covered, a.size() / 4) << "the floor alone covers the lower half of the cube";
  }
}

// A floor of many triangles (so it is cut into several chunks) under the test scene's lid and wall,
// and a deformable copy of the lid beside them.
Scene chunked_scene(std::vector<testing::QuadGeometry>& occluders) {
  Scene scene = testing::make_floor_with_occluders(occluders);
  Mesh& floor = scene.meshes[0];
  floor.positions.clear();
  floor.normals.clear();
  floor.uvs.clear();
  floor.indices.clear();
  constexpr int kCells = 120;  // 28,800 triangles: several chunks of at most kShadowChunkTriangles
  for (int z = 0; z <= kCells; ++z)
    for (int x = 0; x <= kCells; ++x) {
      floor.positions.push_back(vec3(-20.0f + 40.0f * static_cast<float>(x) / kCells, 0.0f,
                                     20.0f - 40.0f * static_cast<float>(z) / kCells));
      floor.normals.push_back(vec3(0.0f, 1.0f, 0.0f));
      floor.uvs.push_back(vec2(static_cast<float>(x), static_cast<float>(z)) / float(kCells));
    }
  for (int z = 0; z < kCells; ++z)
    for (int x = 0; x < kCells; ++x) {
      const auto corner = static_cast<std::uint32_t>(z * (kCells + 1) + x);
      const std::uint32_t next_row = corner + kCells + 1;
      for (const std::uint32_t index : {corner, corner + 1, next_row + 1, corner, next_row + 1, next_row})
        floor.indices.push_back(index);
    }
  Mesh moving = scene.meshes[1];
  moving.deformable = true;
  moving.deform = SineDeform{};
  scene.meshes.push_back(moving);
  Instance instance = scene.instances[1];
  instance.mesh = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  instance.transform = glm::translate(mat4(1.0f), vec3(6.0f, 0.0f, 0.0f));
  scene.instances.push_back(instance);
  return scene;
}

TEST_F(ShadowCube, ChunksCoverEveryTriangleOnceAndCullingChangesNoDepth) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = chunked_scene(occluders);
  const render::GpuScene gpu(scene);
  const render::ShadowChunks chunks(scene, gpu);
  // Every instance's triangles once: chunk sizes add up per instance, within the chunk limit.
  std::vector<std::uint32_t> triangles(scene.instances.size(), 0);
  for (const render::ShadowChunk& chunk : chunks.chunks()) {
    const std::uint32_t instance = chunk.command.base_instance;
    triangles[instance] += chunk.command.count / 3;
    const bool deformable = scene.meshes[scene.instances[instance].mesh].deformable;
    EXPECT_EQ(chunk.world_box.has_value(), !deformable);
    if (!deformable) {
      EXPECT_LE(chunk.command.count / 3, render::kShadowChunkTriangles);
    }
  }
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    EXPECT_EQ(triangles[i], scene.meshes[scene.instances[i].mesh].triangle_count()) << "instance " << i;
  EXPECT_GE(chunks.chunks().size(), 8u);  // the floor alone makes at least 28,800 / 4096 chunks

  for (const vec3 light : {scene.light.position, vec3(1.7f, 1.2f, -0.4f)}) {
    ShadowCubePass culled(kFaceSize, ShadowCubeDraw::per_face), reference(kFaceSize, ShadowCubeDraw::layered);
    culled.run(gpu, light, scene.world_bounds(), &chunks);
    reference.run(gpu, light, scene.world_bounds());
    EXPECT_EQ(read_cube(culled), read_cube(reference)) << "light " << light.x << " " << light.y << " " << light.z;
    // No face needs every chunk (each sees part of the floor), and the deformable lid, which has no
    // box, is in all six.
    for (int face = 0; face < 6; ++face) {
      EXPECT_LT(culled.face_draw_counts()[static_cast<std::size_t>(face)], chunks.chunks().size());
      EXPECT_GE(culled.face_draw_counts()[static_cast<std::size_t>(face)], 1u);
    }
  }
  // Above the centred light only the deformable lid is drawn.
  ShadowCubePass culled(kFaceSize, ShadowCubeDraw::per_face);
  culled.run(gpu, scene.light.position, scene.world_bounds(), &chunks);
  EXPECT_EQ(culled.face_draw_counts()[2], 1u);
}

TEST_F(ShadowCube, DepthIsNearOverTheDistanceAlongTheFaceAxis) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  const render::GpuScene gpu(scene);
  const vec3 light = scene.light.position;  // (0, 4, 0): the lid (y = 2) is straight below it
  for (const ShadowCubeDraw draw : {ShadowCubeDraw::per_face, ShadowCubeDraw::layered}) {
    ShadowCubePass pass(kFaceSize, draw);
    pass.run(gpu, light, scene.world_bounds());
    const std::vector<float> cube = read_cube(pass);
    // -Y (face 3): the lid (y = 2, 2 below the light along the face's axis; |x|, |z| <= 1, so the
    // middle half of the face) under the middle texels, the floor (4 below) at the face's corner.
    for (const int x : {3 * kFaceSize / 8, kFaceSize / 2, 5 * kFaceSize / 8})
      EXPECT_NEAR(pass.near_distance() / texel(cube, 3, x, kFaceSize / 2), 2.0f, 1e-4f) << x;
    EXPECT_NEAR(pass.near_distance() / texel(cube, 3, 0, 0), 4.0f, 1e-4f);
    // +Y (face 2): nothing above the light (depth 0).
    for (int y = 0; y < kFaceSize; ++y)
      for (int x = 0; x < kFaceSize; ++x) ASSERT_EQ(texel(cube, 2, x, y), 0.0f) << x << ", " << y;
  }
  EXPECT_EQ(render::parse_shadow_cube_draw("layered"), ShadowCubeDraw::layered);
  EXPECT_EQ(render::parse_shadow_cube_draw(render::shadow_cube_draw_name(ShadowCubeDraw::per_face)),
            ShadowCubeDraw::per_face);
  EXPECT_THROW(render::parse_shadow_cube_draw("geometry"), Error);
}

}  // namespace
}  // namespace glint
