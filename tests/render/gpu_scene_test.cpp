// GpuScene: the buffer layout the hit-shading pass relies on, in-place vertex updates, bad input.
#include "gl/gl_test_context.h"
#include "gl/read_buffer.h"
#include "raster_test_scene.h"
#include "render/gpu_scene.h"
#include "render/raster_pipeline.h"
#include "support/error_of.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <vector>

namespace glint {
namespace {

using render::GpuScene;
using render::RasterOutput;
using render::RasterPipeline;
using testing::error_of;
using testing::read_buffer;
using GpuSceneTest = testing::GlTest;

// Two meshes, the second drawn twice: ranges, instances and materials say where everything is, and
// the GPU buffers hold exactly that (a compute shader can fetch any triangle of any instance).
TEST_F(GpuSceneTest, BuffersFollowTheDocumentedLayout) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  const std::uint32_t a = testing::add_material(scene, vec3(0.1f, 0.2f, 0.3f), 0.5f);
  const std::uint32_t b = testing::add_material(scene, vec3(0.9f), 0.0f);
  scene.materials[b].emissive = vec3(1.0f, 2.0f, 3.0f);
  testing::add_quad(scene, vec3(0.0f), vec3(1, 0, 0), vec3(0, 1, 0), a);
  testing::add_quad(scene, vec3(5.0f), vec3(0, 0, 2), vec3(0, 3, 0), b);
  Instance copy = scene.instances[1];
  copy.transform = glm::translate(mat4(1.0f), vec3(10.0f, 0.0f, 0.0f)) * glm::scale(mat4(1.0f), vec3(2.0f, 1.0f, 1.0f));
  scene.instances.push_back(copy);
  const GpuScene gpu(scene);

  ASSERT_EQ(gpu.mesh_ranges().size(), 2u);
  EXPECT_EQ(gpu.mesh_ranges()[1].first_index, 6u);
  EXPECT_EQ(gpu.mesh_ranges()[1].index_count, 6u);
  EXPECT_EQ(gpu.mesh_ranges()[1].base_vertex, 4u);
  EXPECT_EQ(gpu.mesh_ranges()[1].vertex_count, 4u);
  ASSERT_EQ(gpu.instances().size(), 3u);
  EXPECT_EQ(gpu.instances()[2].mesh, 1u);
  EXPECT_EQ(gpu.instances()[2].material, b);
  // The normal matrix is the inverse transpose: it keeps normals perpendicular under the x scale.
  const vec3 tangent(1.0f, 1.0f, 0.0f), normal(1.0f, -1.0f, 0.0f);
  EXPECT_NEAR(glm::dot(glm::mat3(gpu.instances()[2].model) * tangent, glm::mat3(gpu.instances()[2].normal_matrix) * normal),
              0.0f, 1e-5f);
  EXPECT_EQ(gpu.materials()[b].emissive, vec4(1.0f, 2.0f, 3.0f, 0.0f));
  EXPECT_EQ(gpu.materials()[a].reflectivity, 0.5f);
  EXPECT_EQ(gpu.materials()[a].texture_layer, -1);

  // Fetch triangle 1 of mesh 1 the way a shader would: indices[first_index + 3p + k] + base_vertex.
  const auto indices = read_buffer<std::uint32_t>(gpu.index_buffer(), 0, 12);
  const auto vertices = read_buffer<render::GpuVertex>(gpu.vertex_buffer(), 0, 8);
  const render::GpuMeshRange range = gpu.mesh_ranges()[1];
  for (int k = 0; k < 3; ++k) {
    const std::uint32_t local = scene.meshes[1].indices[3 + static_cast<std::size_t>(k)];
    EXPECT_EQ(indices[range.first_index + 3 + static_cast<std::uint32_t>(k)], local);
    const render::GpuVertex& vertex = vertices[range.base_vertex + local];
    EXPECT_EQ(vec3(vertex.position_u), scene.meshes[1].positions[local]);
    EXPECT_EQ(vec3(vertex.normal_v), scene.meshes[1].normals[local]);
    EXPECT_EQ(vec2(vertex.position_u.w, vertex.normal_v.w), scene.meshes[1].uvs[local]);
  }
  const auto gpu_instances = read_buffer<render::GpuInstance>(gpu.instance_buffer(), 0, 3);
  EXPECT_EQ(gpu_instances[2].model, copy.transform);
  const auto gpu_materials = read_buffer<render::GpuMaterial>(gpu.material_buffer(), 0, 2);
  EXPECT_EQ(gpu_materials[b].diffuse, vec4(0.9f, 0.9f, 0.9f, 1.0f));
}

// Moving a quad's vertices in place (as a deformer does) moves it in the next G-buffer, normals
// included; uvs stay.
TEST_F(GpuSceneTest, UpdateMeshVerticesMovesTheGeometry) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  const std::uint32_t grey = testing::add_material(scene, vec3(0.5f));
  testing::add_quad(scene, vec3(-1.0f, -1.0f, -8.0f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 1.0f, 0.0f), grey);  // off centre
  const std::uint32_t moving =
      testing::add_quad(scene, vec3(-2.0f, -2.0f, -5.0f), vec3(4.0f, 0.0f, 0.0f), vec3(0.0f, 4.0f, 0.0f), grey);
  RasterPipeline raster(scene, 32, 32);
  const FrameState frame = testing::look_at(vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), scene.light.position);
  raster.render(frame);
  EXPECT_NEAR(raster.read_rgbaf(RasterOutput::WorldPosition).at(16, 16).z, -5.0f, 5e-3f);

  // Tilt the quad: z = -3 - 0.5 x, normal (0.5, 0, 1) normalised.
  std::vector<vec3> positions = scene.meshes[moving].positions;
  for (vec3& p : positions) p.z = -3.0f - 0.5f * p.x;
  const std::vector<vec3> normals(4, glm::normalize(vec3(0.5f, 0.0f, 1.0f)));
  raster.gpu_scene().update_mesh_vertices(moving, positions, normals);
  raster.render(frame);
  const ImageRgbaF position = raster.read_rgbaf(RasterOutput::WorldPosition);
  const ImageRgbaF normal = raster.read_rgbaf(RasterOutput::WorldNormalRoughness);
  for (const int x : {8, 16, 24}) {
    const vec4 p = position.at(x, 16);
    EXPECT_NEAR(p.z, -3.0f - 0.5f * p.x, 2e-3f) << "pixel x " << x;
    EXPECT_NEAR(glm::length(vec3(normal.at(x, 16)) - normals[0]), 0.0f, 2e-3f);
  }
  // The other mesh is untouched, uvs kept.
  const auto vertices = read_buffer<render::GpuVertex>(raster.gpu_scene().vertex_buffer(), 0, 8);
  EXPECT_EQ(vec3(vertices[0].position_u), scene.meshes[0].positions[0]);
  EXPECT_EQ(vec2(vertices[6].position_u.w, vertices[6].normal_v.w), scene.meshes[moving].uvs[2]);
  EXPECT_EQ(vec3(vertices[6].position_u), positions[2]);
}

TEST_F(GpuSceneTest, BadUpdatesAreErrors) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  testing::add_quad(scene, vec3(0.0f), vec3(1, 0, 0), vec3(0, 1, 0), testing::add_material(scene, vec3(0.5f)));
  GpuScene gpu(scene);
  const std::vector<vec3> four(4, vec3(0.0f, 0.0f, 1.0f)), three(3, vec3(0.0f, 0.0f, 1.0f));
  EXPECT_NE(error_of([&] { gpu.update_mesh_vertices(0, three, three); }).find("mesh 0 has 4 vertices but got 3 positions and 3 normals"),
            std::string::npos);
  EXPECT_NE(error_of([&] { gpu.update_mesh_vertices(0, four, three); }).find("got 4 positions and 3 normals"),
            std::string::npos);
  EXPECT_NE(error_of([&] { gpu.update_mesh_vertices(1, four, four); }).find("mesh 1 does not exist"), std::string::npos);
}

TEST_F(GpuSceneTest, InvalidScenesAndSettingsAreErrors) {
  Scene empty = testing::make_empty_test_scene(vec3(0.0f));
  EXPECT_NE(error_of([&] { GpuScene gpu(empty); }).find("empty"), std::string::npos);

  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  testing::add_quad(scene, vec3(0.0f), vec3(1, 0, 0), vec3(0, 1, 0), testing::add_material(scene, vec3(0.5f)));
  Texture broken;
  broken.name = "broken.png";
  broken.width = broken.height = 4;
  broken.rgba.resize(10);
  scene.textures.push_back(broken);
  EXPECT_NE(error_of([&] { GpuScene gpu(scene); }).find("texture 'broken.png': 4x4 texels but 10 bytes"), std::string::npos);
  scene.textures.clear();

  render::RasterSettings settings;
  settings.shadow_map_size = 0;
  EXPECT_NE(error_of([&] { RasterPipeline raster(scene, 8, 8, settings); }).find("shadow_map_size"), std::string::npos);
  settings = {};
  settings.pcf_radius_texels = -1.0f;
  EXPECT_NE(error_of([&] { RasterPipeline raster(scene, 8, 8, settings); }).find("pcf_radius_texels"), std::string::npos);
  settings = {};
  settings.shadow_map_size = 1 << 20;
  EXPECT_NE(error_of([&] { RasterPipeline raster(scene, 8, 8, settings); }).find("shadow cube map: size"), std::string::npos);
  EXPECT_NE(error_of([&] { RasterPipeline raster(scene, 0, 8); }).find("invalid size 0x8"), std::string::npos);
}

}  // namespace
}  // namespace glint
