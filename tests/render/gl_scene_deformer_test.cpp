// GlSceneDeformer (--deform-on gpu's GL half) against the CPU deformer: the vertex buffer it poses
// must hold SineDeformer's positions and normals, and leave every other mesh and the uvs alone.
#include "render/gl_scene_deformer.h"

#include "gl/gl_test_context.h"
#include "render/gpu_scene.h"
#include "scene/presets.h"
#include "scene/sine_deformer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace glint::render {
namespace {

using GlSceneDeformerTest = glint::testing::GlTest;

std::vector<GpuVertex> read_vertices(const GpuScene& scene) {
  std::size_t count = 0;
  for (const GpuMeshRange& range : scene.mesh_ranges()) count = std::max<std::size_t>(count, range.base_vertex + range.vertex_count);
  std::vector<GpuVertex> vertices(count);
  glGetNamedBufferSubData(scene.vertex_buffer(), 0, static_cast<GLsizeiptr>(count * sizeof(GpuVertex)), vertices.data());
  return vertices;
}

// The atrium's two dinosaurs at walkthrough frames 0, 2100 and 4899 (a large phase, where a sine's
// argument reduction would show), against SceneDeformers on the CPU.
TEST_F(GlSceneDeformerTest, PosesTheVertexBufferAsTheCpuDeformerPosesTheMeshes) {
  Scene scene = make_preset("atrium");
  const SceneDeformers deformers(scene);
  ASSERT_FALSE(deformers.empty()) << "the atrium's dinosaurs deform";
  GpuScene gpu(scene);
  const std::vector<GpuVertex> rest = read_vertices(gpu);
  GlSceneDeformer deformer(deformers, gpu);
  EXPECT_EQ(deformer.meshes(), deformers.meshes());

  for (const int frame : {0, 2100, 4899}) {
    Scene posed = scene;
    SceneDeformers(posed).apply(posed, frame);
    deformer.apply(frame);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<GpuVertex> vertices = read_vertices(gpu);
    float position_error = 0.0f, normal_error = 0.0f, extent = 0.0f;
    int moved = 0;
    for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
      const GpuMeshRange& range = gpu.mesh_ranges()[m];
      const bool deforms = std::find(deformers.meshes().begin(), deformers.meshes().end(), m) != deformers.meshes().end();
      for (std::uint32_t i = 0; i < range.vertex_count; ++i) {
        const GpuVertex& got = vertices[range.base_vertex + i];
        const GpuVertex& before = rest[range.base_vertex + i];
        EXPECT_EQ(got.position_u.w, before.position_u.w) << "u of mesh " << m << " vertex " << i;
        EXPECT_EQ(got.normal_v.w, before.normal_v.w) << "v of mesh " << m << " vertex " << i;
        if (!deforms) {
          ASSERT_EQ(vec3(got.position_u), vec3(before.position_u)) << "mesh " << m << " does not deform";
          continue;
        }
        const vec3 want = posed.meshes[m].positions[i];
        position_error = std::max(position_error, glm::length(vec3(got.position_u) - want));
        normal_error = std::max(normal_error, glm::length(vec3(got.normal_v) - posed.meshes[m].normals[i]));
        extent = std::max({extent, std::abs(want.x), std::abs(want.y), std::abs(want.z)});
        moved += vec3(got.position_u) != vec3(before.position_u);
      }
    }
    EXPECT_GT(moved, 100) << "frame " << frame << ": the dinosaurs must move";
    std::printf("frame %d: largest position error %g (extent %g), normal error %g\n", frame, position_error, extent, normal_error);
    // Float rounding of sin and of the sums (llvmpipe and NVIDIA's GL evaluate sin their own way).
    // Measured on llvmpipe: positions 2.4e-7 off (extent 3.2), normals 4.3e-6.
    EXPECT_LE(position_error, 1e-5f * std::max(extent, 1.0f)) << "frame " << frame;
    EXPECT_LE(normal_error, 1e-3f) << "frame " << frame;
  }
}

}  // namespace
}  // namespace glint::render
