// GlSceneDeformer (--deform-on gpu's GL half) against the CPU deformer: the vertex buffer it poses
// must hold SineDeformer's positions and normals, and leave every other mesh and the uvs alone; with
// every mesh in the same two dispatches, each mesh must find its own job, and the posed positions
// handed to gpu_deformation.cpp must sit at each mesh's offset. Also the grid its dispatches (and the
// gl backend's refit's) are sized by, gl/compute_grid.h.
#include "render/gl_scene_deformer.h"

#include "gl/compute_grid.h"
#include "gl/gl_test_context.h"
#include "gl/read_buffer.h"
#include "raster_test_scene.h"
#include "render/gpu_scene.h"
#include "scene/presets.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
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

// A columns x rows grid of quads (two triangles each) in the xz plane from `origin`, cell `cell`
// wide, with uvs, as its own mesh and instance: (columns + 1)(rows + 1) vertices, 2 columns rows
// triangles. Deforms with `deform` when given. Returns the mesh index.
std::uint32_t add_grid(Scene& scene, vec3 origin, int columns, int rows, float cell, std::optional<SineDeform> deform) {
  Mesh mesh;
  mesh.name = "grid" + std::to_string(scene.meshes.size());
  for (int r = 0; r <= rows; ++r) {
    for (int c = 0; c <= columns; ++c) {
      mesh.positions.push_back(origin + vec3(static_cast<float>(c) * cell, 0.0f, -static_cast<float>(r) * cell));
      mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
      mesh.uvs.emplace_back(static_cast<float>(c) / static_cast<float>(columns), static_cast<float>(r) / static_cast<float>(rows));
    }
  }
  const auto at = [columns](int c, int r) { return static_cast<std::uint32_t>(r * (columns + 1) + c); };
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      mesh.indices.insert(mesh.indices.end(), {at(c, r), at(c + 1, r), at(c + 1, r + 1)});
      mesh.indices.insert(mesh.indices.end(), {at(c, r), at(c + 1, r + 1), at(c, r + 1)});
    }
  }
  mesh.deformable = deform.has_value();
  mesh.deform = deform;
  scene.meshes.push_back(std::move(mesh));
  const std::uint32_t index = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  Instance instance;
  instance.name = scene.meshes.back().name;
  instance.mesh = index;
  scene.instances.push_back(instance);
  return index;
}

// Three deforming meshes of different sizes and deformations, none a multiple of the work group
// (so meshes share work groups in both dispatches), with static meshes before and between them: a
// grid with more triangles than vertices (its triangles set its share of the pose dispatch), a strip
// with more vertices than triangles (its vertices do), and a small grid last.
Scene three_deforming_meshes() {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 4.0f, 0.0f));
  testing::add_material(scene, vec3(0.5f));
  testing::add_quad(scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), 0);
  add_grid(scene, vec3(-3.0f, 1.0f, 2.0f), 20, 15, 0.2f, SineDeform{1, 0, 0.3f, 3.0f, 1.5f});  // 336 vertices, 600 triangles
  add_grid(scene, vec3(2.0f, 0.5f, 1.0f), 3, 2, 0.5f, std::nullopt);                           // static, between them
  add_grid(scene, vec3(-5.0f, 2.0f, -1.0f), 100, 1, 0.1f, SineDeform{2, 0, 0.2f, 5.0f, 2.5f});  // 202 vertices, 200 triangles
  add_grid(scene, vec3(1.0f, 3.0f, -2.0f), 7, 5, 0.3f, SineDeform{0, 2, 0.15f, 2.0f, -1.0f});  // 48 vertices, 70 triangles
  scene.validate();
  return scene;
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

// Every mesh in the same two dispatches: each deforming mesh posed as the CPU poses it, whatever
// its share of the dispatches, and the static meshes between them untouched.
TEST_F(GlSceneDeformerTest, PosesEveryMeshOfAThreeMeshSceneAsTheCpuDeformer) {
  const Scene scene = three_deforming_meshes();
  const SceneDeformers deformers(scene);
  ASSERT_EQ(deformers.meshes(), (std::vector<std::uint32_t>{1, 3, 4}));
  GpuScene gpu(scene);
  const std::vector<GpuVertex> rest = read_vertices(gpu);
  GlSceneDeformer deformer(deformers, gpu);

  for (const int frame : {0, 7, 2100}) {
    Scene posed = scene;
    SceneDeformers(posed).apply(posed, frame);
    deformer.apply(frame);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<GpuVertex> vertices = read_vertices(gpu);
    for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
      const GpuMeshRange& range = gpu.mesh_ranges()[m];
      ASSERT_EQ(range.vertex_count, scene.meshes[m].vertex_count());
      const bool deforms = scene.meshes[m].deformable;
      float position_error = 0.0f, normal_error = 0.0f;
      int moved = 0;
      for (std::uint32_t i = 0; i < range.vertex_count; ++i) {
        const GpuVertex& got = vertices[range.base_vertex + i];
        const GpuVertex& before = rest[range.base_vertex + i];
        EXPECT_EQ(got.position_u.w, before.position_u.w) << "u of mesh " << m << " vertex " << i;
        EXPECT_EQ(got.normal_v.w, before.normal_v.w) << "v of mesh " << m << " vertex " << i;
        if (!deforms) {
          ASSERT_EQ(vec3(got.position_u), vec3(before.position_u)) << "mesh " << m << " does not deform";
          ASSERT_EQ(vec3(got.normal_v), vec3(before.normal_v)) << "mesh " << m << " does not deform";
          continue;
        }
        position_error = std::max(position_error, glm::length(vec3(got.position_u) - posed.meshes[m].positions[i]));
        normal_error = std::max(normal_error, glm::length(vec3(got.normal_v) - posed.meshes[m].normals[i]));
        moved += vec3(got.position_u) != vec3(before.position_u);
      }
      if (!deforms) continue;
      // The atrium test's bounds, 1e-5 of the extent (under 6 here) for the positions.
      EXPECT_LE(position_error, 6e-5f) << "mesh " << m << ", frame " << frame;
      EXPECT_LE(normal_error, 1e-3f) << "mesh " << m << ", frame " << frame;
      EXPECT_GT(moved, static_cast<int>(range.vertex_count) / 2) << "mesh " << m << ", frame " << frame;
    }
  }
}

// What the gl backend's GPU refit reads (gpu_deformation.cpp): with write_positions_to, each mesh's
// positions at its first vertex of the target buffer, exactly the positions the normals stage wrote
// into that mesh's vertices (w 0), and nothing else of the buffer touched; a new layout moves them.
TEST_F(GlSceneDeformerTest, WritesEachMeshsPositionsWhereItIsTold) {
  const Scene scene = three_deforming_meshes();
  const SceneDeformers deformers(scene);
  GpuScene gpu(scene);
  GlSceneDeformer deformer(deformers, gpu);
  std::uint32_t total = 0;
  for (const std::uint32_t mesh : deformer.meshes()) total += gpu.mesh_ranges()[mesh].vertex_count;
  const vec4 sentinel(-7.0f, 3.5f, 1e9f, 42.0f);
  const std::vector<vec4> filler(total + 64, sentinel);
  const GlBuffer target = create_buffer(std::span<const vec4>(filler), GL_DYNAMIC_STORAGE_BIT);
  // Meshes in reverse order with gaps between them, then packed in order from vertex 0.
  for (const bool reversed : {true, false}) {
    std::vector<std::uint32_t> first(deformer.meshes().size());
    std::uint32_t next = reversed ? 5u : 0u;
    for (std::size_t n = 0; n < first.size(); ++n) {
      const std::size_t k = reversed ? first.size() - 1 - n : n;
      first[k] = next;
      next += gpu.mesh_ranges()[deformer.meshes()[k]].vertex_count + (reversed ? 7u : 0u);
    }
    ASSERT_LE(next, filler.size());
    glNamedBufferSubData(target.id(), 0, static_cast<GLsizeiptr>(filler.size() * sizeof(vec4)), filler.data());
    deformer.write_positions_to(target.id(), first);
    deformer.apply(reversed ? 2100 : 7);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    const std::vector<GpuVertex> vertices = read_vertices(gpu);
    const std::vector<vec4> written = testing::read_buffer<vec4>(target.id(), 0, filler.size());
    std::vector<bool> covered(filler.size(), false);
    for (std::size_t k = 0; k < first.size(); ++k) {
      const GpuMeshRange& range = gpu.mesh_ranges()[deformer.meshes()[k]];
      for (std::uint32_t i = 0; i < range.vertex_count; ++i) {
        covered[first[k] + i] = true;
        ASSERT_EQ(vec3(written[first[k] + i]), vec3(vertices[range.base_vertex + i].position_u)) << "mesh " << k << " vertex " << i;
        ASSERT_EQ(written[first[k] + i].w, 0.0f) << "mesh " << k << " vertex " << i;
      }
    }
    for (std::size_t v = 0; v < filler.size(); ++v) {
      if (covered[v]) continue;
      ASSERT_EQ(written[v], sentinel) << "vertex " << v << " of the target is no mesh's";
    }
  }
  const std::vector<std::uint32_t> too_few(deformer.meshes().size() - 1, 0u);
  EXPECT_NE(testing::error_of([&] { deformer.write_positions_to(target.id(), too_few); }).find("one per deforming mesh"),
            std::string::npos);
}

// grid_of_work_groups: columns first, up to 65,535, then rows; an error naming the dispatch past GL's
// 65,535 x 65,535 groups or past 2^32 invocation indices (grid_invocation() counts in uint).
TEST(GlSceneDeformerComputeGrid, FillsColumnsThenRowsAndRefusesWhatDoesNotFit) {
  constexpr std::uint64_t kColumns = 65535;
  EXPECT_EQ(grid_of_work_groups(0, 64, "test"), (ComputeGrid{0, 0}));
  EXPECT_EQ(grid_of_work_groups(1, 64, "test"), (ComputeGrid{1, 1}));
  EXPECT_EQ(grid_of_work_groups(64, 64, "test"), (ComputeGrid{1, 1}));
  EXPECT_EQ(grid_of_work_groups(65, 64, "test"), (ComputeGrid{2, 1}));
  EXPECT_EQ(grid_of_work_groups(kColumns * 64, 64, "test"), (ComputeGrid{65535, 1}));
  EXPECT_EQ(grid_of_work_groups(kColumns * 64 + 1, 64, "test"), (ComputeGrid{65535, 2}));
  // The most groups of 64 whose indices stay below 2^32: 1,024 full rows.
  EXPECT_EQ(grid_of_work_groups(kColumns * 1024 * 64, 64, "test"), (ComputeGrid{65535, 1024}));
  const std::string wraps =
      testing::error_of([] { grid_of_work_groups(kColumns * 1024 * 64 + 1, 64, "GL deformer: pose stage"); });
  EXPECT_NE(wraps.find("GL deformer: pose stage: "), std::string::npos) << wraps;
  EXPECT_NE(wraps.find("2^32"), std::string::npos) << wraps;
  EXPECT_NE(wraps.find("65535 x 1025"), std::string::npos) << wraps;
  // In groups of 1 the full grid fits 32-bit indices; one more invocation does not fit the grid.
  EXPECT_EQ(grid_of_work_groups(kColumns * kColumns, 1, "test"), (ComputeGrid{65535, 65535}));
  const std::string too_many = testing::error_of([] { grid_of_work_groups(kColumns * kColumns + 1, 1, "rt gl: TLAS refit"); });
  EXPECT_NE(too_many.find("rt gl: TLAS refit: 4294836226 invocations"), std::string::npos) << too_many;
  EXPECT_NE(too_many.find("more than GL's 65,535 x 65,535 grid holds"), std::string::npos) << too_many;
  const std::string beyond = testing::error_of([] { grid_of_work_groups(kColumns * kColumns * 64 + 1, 64, "test"); });
  EXPECT_NE(beyond.find("more than GL's 65,535 x 65,535 grid holds"), std::string::npos) << beyond;
  EXPECT_NE(testing::error_of([] { grid_of_work_groups(~std::uint64_t{0}, 64, "test"); }).find("grid holds"),
            std::string::npos);
  EXPECT_NE(testing::error_of([] { grid_of_work_groups(1, 0, "test"); }).find("work groups of 0"), std::string::npos);
}

}  // namespace
}  // namespace glint::render
