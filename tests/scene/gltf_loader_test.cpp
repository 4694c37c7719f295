#include "scene/gltf_loader.h"

#include "core/error.h"
#include "core/log.h"
#include "scene/gltf_materials.h"
#include "scene/gltf_test_builder.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace glint {
namespace {

using testing::GltfBuilder;
using testing::TempFolder;
using nlohmann::json;

vec3 world_position(const Scene& scene, const Instance& instance, std::size_t vertex) {
  return vec3(instance.transform * vec4(scene.meshes[instance.mesh].positions[vertex], 1.0f));
}

void expect_near(const vec3& actual, const vec3& expected) {
  EXPECT_NEAR(actual.x, expected.x, 1e-5f);
  EXPECT_NEAR(actual.y, expected.y, 1e-5f);
  EXPECT_NEAR(actual.z, expected.z, 1e-5f);
}

// Expects load_gltf to throw a glint::Error whose message contains every one of `parts`.
void expect_error(const std::filesystem::path& file, std::initializer_list<std::string> parts) {
  try {
    load_gltf(file);
    ADD_FAILURE() << "no error for " << file;
  } catch (const Error& e) {
    for (const std::string& part : parts) EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(GltfLoader, ComposesNodeHierarchyTransformsParentTimesChild) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3(testing::unit_triangle());
  // Node 0: translate (10, 0, 0), child node 1: rotate 90 degrees about +y and scale 2, with the mesh.
  const int child = gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}},
                                       {{"rotation", {0.0, std::sqrt(0.5), 0.0, std::sqrt(0.5)}}, {"scale", {2, 2, 2}}});
  gltf.json["nodes"].push_back({{"translation", {10, 0, 0}}, {"children", {child}}});
  // Node 2: the same mesh through a column-major "matrix" (translate (0, 5, 0)).
  gltf.json["nodes"].push_back({{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1}}});
  TempFolder folder;
  const Scene scene = load_gltf(folder.write("hierarchy.gltf", gltf.gltf_text()));

  ASSERT_EQ(scene.meshes.size(), 1u);  // one mesh, two nodes use it
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.source, (folder.path() / "hierarchy.gltf").string());
  const Instance* nested = nullptr;
  const Instance* by_matrix = nullptr;
  for (const Instance& instance : scene.instances) (instance.transform[3].y > 1.0f ? by_matrix : nested) = &instance;
  ASSERT_TRUE(nested && by_matrix);
  // (1, 0, 0): scaled to (2, 0, 0), rotated 90 degrees about y to (0, 0, -2), then moved by (10, 0, 0).
  expect_near(world_position(scene, *nested, 1), vec3(10.0f, 0.0f, -2.0f));
  expect_near(world_position(scene, *nested, 2), vec3(10.0f, 2.0f, 0.0f));
  expect_near(world_position(scene, *by_matrix, 1), vec3(1.0f, 5.0f, 0.0f));
}

TEST(GltfLoader, EachTrianglePrimitiveBecomesAMeshAndNormalsAreComputedWhenAbsent) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3(testing::unit_triangle());
  // A quad in the xz plane facing +y, made of two triangles sharing an edge.
  const int quad = gltf.add_vec3({0, 0, 0, 0, 0, 1, 1, 0, 1, 1, 0, 0});
  const int quad_indices = gltf.add_indices_u16({0, 1, 2, 0, 2, 3});
  gltf.json["meshes"].push_back({{"name", "pair"},
                                 {"primitives",
                                  {{{"attributes", {{"POSITION", positions}}}},
                                   {{"attributes", {{"POSITION", quad}}}, {"indices", quad_indices}}}}});
  gltf.json["nodes"].push_back({{"mesh", 0}, {"name", "thing"}});
  TempFolder folder;
  const Scene scene = load_gltf(folder.write("pair.gltf", gltf.gltf_text()));

  ASSERT_EQ(scene.meshes.size(), 2u);
  EXPECT_EQ(scene.meshes[0].name, "pair/0");
  EXPECT_EQ(scene.meshes[1].name, "pair/1");
  EXPECT_EQ(scene.instances.size(), 2u);
  EXPECT_EQ(scene.triangle_count(), 3u);
  ASSERT_EQ(scene.meshes[1].normals.size(), 4u);
  for (const vec3& normal : scene.meshes[1].normals) expect_near(normal, vec3(0.0f, 1.0f, 0.0f));
  for (const vec3& normal : scene.meshes[0].normals) expect_near(normal, vec3(0.0f, 0.0f, 1.0f));

  LoadOptions flat;
  flat.flat_normals = true;
  const Scene faceted = load_gltf(folder.path() / "pair.gltf", flat);
  EXPECT_EQ(faceted.meshes[1].positions.size(), 6u);  // flat normals give each triangle its own vertices
}

TEST(GltfLoader, ReadsIndicesOfEveryComponentTypeAndNoneAsSequential) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  const int u8 = gltf.add_indices_u8({0, 1, 3});
  const int u16 = gltf.add_indices_u16({0, 1, 3});
  const int u32 = gltf.add_indices_u32({0, 1, 3});
  const int three = gltf.add_vec3(testing::unit_triangle());
  for (int indices : {u8, u16, u32}) gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", three}}}});
  TempFolder folder;
  const Scene scene = load_gltf(folder.write("indices.gltf", gltf.gltf_text()));
  ASSERT_EQ(scene.meshes.size(), 4u);
  for (int m = 0; m < 3; ++m) EXPECT_EQ(scene.meshes[static_cast<std::size_t>(m)].indices, (std::vector<std::uint32_t>{0, 1, 3}));
  EXPECT_EQ(scene.meshes[3].indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(GltfLoader, ConvertsTriangleStripsAndSkipsPointsWithOneWarning) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"mode", 5}});  // strip: 2 triangles
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"mode", 0}});  // points
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"mode", 1}});  // lines
  TempFolder folder;
  ScopedLogCapture log;
  const Scene scene = load_gltf(folder.write("strip.gltf", gltf.gltf_text()));
  ASSERT_EQ(scene.meshes.size(), 1u);
  // Both strip triangles keep the counter-clockwise winding: normals face +z.
  EXPECT_EQ(scene.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));
  for (const vec3& normal : scene.meshes[0].normals) expect_near(normal, vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(log.count_warnings("skipped 2 primitive"), 1);
}

TEST(GltfLoader, MapsMetallicRoughnessMaterials) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3(testing::unit_triangle());
  gltf.json["materials"].push_back({{"name", "chrome"},
                                    {"pbrMetallicRoughness",
                                     {{"baseColorFactor", {0.5, 0.25, 1.0, 1.0}}, {"metallicFactor", 1.0}, {"roughnessFactor", 0.25}}},
                                    {"emissiveFactor", {0.1, 0.2, 0.3}}});
  gltf.json["materials"].push_back({{"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"material", 0}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"material", 1}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}});  // glTF's default material
  TempFolder folder;
  const Scene scene = load_gltf(folder.write("materials.gltf", gltf.gltf_text()));
  ASSERT_EQ(scene.materials.size(), 3u);
  const Material& chrome = scene.materials[scene.meshes[0].material];
  EXPECT_EQ(chrome.name, "chrome");
  expect_near(chrome.diffuse, vec3(0.5f, 0.25f, 1.0f));
  // Metallic 1 mirrors fully; the roughness widens the reflection (roughness) and does not also
  // weaken it (it once gave metallic x (1 - roughness) = 0.75).
  EXPECT_FLOAT_EQ(chrome.reflectivity, 1.0f);
  EXPECT_FLOAT_EQ(chrome.roughness, 0.25f);
  expect_near(chrome.specular, chrome.diffuse);  // metals reflect their own colour
  expect_near(chrome.emissive, vec3(0.1f, 0.2f, 0.3f));
  EXPECT_FLOAT_EQ(chrome.specular_exponent, specular_exponent_from_roughness(0.25f));

  const Material& plastic = scene.materials[scene.meshes[1].material];
  EXPECT_EQ(plastic.name, "materials[1]");
  EXPECT_FLOAT_EQ(plastic.reflectivity, 0.0f);
  expect_near(plastic.specular, vec3(0.04f));
  EXPECT_FLOAT_EQ(plastic.specular_exponent, 30.0f);  // roughness 0.5: 2 / 0.25^2 - 2
  const Material& fallback = scene.materials[scene.meshes[2].material];
  EXPECT_EQ(fallback.name, "default");
  EXPECT_FLOAT_EQ(fallback.reflectivity, 0.0f);  // glTF's default is a rough metal; glint's is no mirror
  expect_near(fallback.diffuse, vec3(1.0f));
}

TEST(GltfLoader, MetallicRoughnessTextureScalesTheFactorsByItsMeans) {
  GltfBuilder gltf;
  // 2x2, linear: G (roughness) 0, 102, 204, 255 -> mean 0.55; B (metallic) 255, 255, 0, 0 -> mean 0.5.
  // R and A are unused by glTF and set to disturb a wrong channel.
  const std::vector<std::uint8_t> pixels = {9, 0, 255, 17, 9, 102, 255, 17, 9, 204, 0, 17, 9, 255, 0, 17};
  const int image = gltf.add_png_image(testing::encode_png(2, 2, pixels));
  gltf.json["textures"].push_back({{"source", image}});
  gltf.json["materials"].push_back(
      {{"name", "worn metal"},
       {"pbrMetallicRoughness",
        {{"metallicFactor", 0.8}, {"roughnessFactor", 0.5}, {"metallicRoughnessTexture", {{"index", 0}}}}}});
  // Only the texture: the factors default to 1.
  gltf.json["materials"].push_back({{"pbrMetallicRoughness", {{"metallicRoughnessTexture", {{"index", 0}}}}}});
  const int positions = gltf.add_vec3(testing::unit_triangle());
  const int uvs = gltf.add_vec2({0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", 0}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", 1}});
  TempFolder folder;
  const Scene scene = load_gltf(folder.write("worn.gltf", gltf.gltf_text()));
  EXPECT_TRUE(scene.textures.empty()) << "the texture is folded into the material, not drawn";
  const Material& worn = scene.materials[scene.meshes[0].material];
  EXPECT_EQ(worn.diffuse_texture, -1);
  EXPECT_NEAR(worn.roughness, 0.5f * 0.55f, 1e-5f);
  EXPECT_NEAR(worn.reflectivity, 0.8f * 0.5f, 1e-5f);
  EXPECT_NEAR(worn.specular_exponent, specular_exponent_from_roughness(0.5f * 0.55f), 1e-3f);
  expect_near(worn.specular, glm::mix(vec3(0.04f), vec3(1.0f), 0.4f));
  const Material& bare = scene.materials[scene.meshes[1].material];
  EXPECT_NEAR(bare.roughness, 0.55f, 1e-5f);
  EXPECT_NEAR(bare.reflectivity, 0.5f, 1e-5f);
}

TEST(GltfLoader, MissingMetallicRoughnessImageLeavesTheFactorsWithAWarning) {
  GltfBuilder gltf;
  gltf.json["images"].push_back({{"uri", "gone.png"}});
  gltf.json["textures"].push_back({{"source", 0}});
  gltf.json["materials"].push_back(
      {{"pbrMetallicRoughness",
        {{"metallicFactor", 0.6}, {"roughnessFactor", 0.3}, {"metallicRoughnessTexture", {{"index", 0}}}}}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}, {"material", 0}});
  TempFolder folder;
  ScopedLogCapture log;
  const Scene scene = load_gltf(folder.write("gone.gltf", gltf.gltf_text()));
  EXPECT_EQ(log.count_warnings("image \"gone.png\" could not be loaded"), 1);
  const Material& material = scene.materials[scene.meshes[0].material];
  EXPECT_FLOAT_EQ(material.roughness, 0.3f);
  EXPECT_FLOAT_EQ(material.reflectivity, 0.6f);
}

TEST(GltfLoader, SpecularExponentFallsWithRoughnessWithinItsClamp) {
  EXPECT_FLOAT_EQ(specular_exponent_from_roughness(0.0f), 2048.0f);
  EXPECT_FLOAT_EQ(specular_exponent_from_roughness(1.0f), 1.0f);
  EXPECT_GT(specular_exponent_from_roughness(0.3f), specular_exponent_from_roughness(0.6f));
}

TEST(GltfLoader, DecodesEmbeddedBaseColorTextureTopRowFirstAndFlipsV) {
  GltfBuilder gltf;
  // 2x2: top row red, green; bottom row blue, white (half transparent).
  const std::vector<std::uint8_t> pixels = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 255, 255, 255, 128};
  const int image = gltf.add_png_image(testing::encode_png(2, 2, pixels));
  gltf.json["textures"].push_back({{"source", image}});
  gltf.json["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  const int positions = gltf.add_vec3(testing::unit_triangle());
  const int uvs = gltf.add_vec2({0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.75f});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", 0}});
  TempFolder folder;
  const Scene scene = load_gltf(folder.write("textured.gltf", gltf.gltf_text()));
  ASSERT_EQ(scene.textures.size(), 1u);
  const Texture& texture = scene.textures[0];
  EXPECT_EQ(texture.width, 2);
  EXPECT_EQ(texture.height, 2);
  EXPECT_EQ(texture.rgba, pixels);
  EXPECT_FALSE(texture.placeholder);
  EXPECT_EQ(scene.materials[scene.meshes[0].material].diffuse_texture, 0);
  // glTF v = 0 is the image's top edge; glint's v = 0 is its bottom edge.
  ASSERT_EQ(scene.meshes[0].uvs.size(), 3u);
  EXPECT_FLOAT_EQ(scene.meshes[0].uvs[0].y, 1.0f);
  EXPECT_FLOAT_EQ(scene.meshes[0].uvs[2].y, 0.25f);
}

TEST(GltfLoader, MissingExternalImageLeavesTheMaterialUntexturedWithAWarning) {
  GltfBuilder gltf;
  gltf.json["images"].push_back({{"uri", "nowhere.png"}});
  gltf.json["textures"].push_back({{"source", 0}});
  gltf.json["materials"].push_back({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}, {"material", 0}});
  TempFolder folder;
  ScopedLogCapture log;
  const Scene scene = load_gltf(folder.write("lost.gltf", gltf.gltf_text()));
  EXPECT_TRUE(scene.textures.empty());
  EXPECT_EQ(scene.materials[0].diffuse_texture, -1);
  EXPECT_EQ(log.count_warnings("image \"nowhere.png\" could not be loaded"), 1);
}

TEST(GltfLoader, LoadsGlbAndExternalBinLikeEmbeddedGltf) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3({0, 0, 0, 2, 0, 0, 0, 3, 0});
  const int normals = gltf.add_vec3({0, 0, 2, 0, 0, 1, 0, 0, 1});  // not unit: normalized on load
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}}, {{"translation", {0, 0, 7}}});
  TempFolder folder;
  folder.write("model.bin", gltf.bin());
  for (const std::filesystem::path& file : {folder.write("model.glb", gltf.glb()),
                                            folder.write("split.gltf", gltf.gltf_text_with_bin("model.bin")),
                                            folder.write("inline.gltf", gltf.gltf_text())}) {
    SCOPED_TRACE(file.string());
    const Scene scene = load_gltf(file);
    ASSERT_EQ(scene.instances.size(), 1u);
    expect_near(world_position(scene, scene.instances[0], 2), vec3(0.0f, 3.0f, 7.0f));
    expect_near(scene.meshes[0].normals[0], vec3(0.0f, 0.0f, 1.0f));
    EXPECT_EQ(scene.name, file.stem().string());
    EXPECT_FALSE(scene.walkthrough.camera.points.empty());  // the default walkthrough
  }
}

TEST(GltfLoader, UsesTheDefaultSceneElseAllRootNodes) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3(testing::unit_triangle());
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}});
  gltf.json["nodes"].push_back({{"mesh", 0}, {"translation", {0, 9, 0}}});
  TempFolder folder;
  EXPECT_EQ(load_gltf(folder.write("roots.gltf", gltf.gltf_text())).instances.size(), 2u);
  gltf.json["scenes"] = json::array({{{"nodes", {1}}}});
  gltf.json["scene"] = 0;
  const Scene scene = load_gltf(folder.write("chosen.gltf", gltf.gltf_text()));
  ASSERT_EQ(scene.instances.size(), 1u);
  EXPECT_FLOAT_EQ(scene.instances[0].transform[3].y, 9.0f);
}

TEST(GltfLoader, DropsDegenerateTrianglesWithOneWarningGivingTheCount) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3({0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0});
  const int indices = gltf.add_indices_u16({0, 1, 2, 0, 0, 1, 0, 1, 3});  // 2nd repeats a vertex, 3rd is collinear
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
  TempFolder folder;
  ScopedLogCapture log;
  const Scene scene = load_gltf(folder.write("thin.gltf", gltf.gltf_text()));
  EXPECT_EQ(scene.triangle_count(), 1u);
  EXPECT_EQ(log.count_warnings("dropped 2 degenerate"), 1);
}

TEST(GltfLoader, ErrorsNameTheFileAndTheGltfLocation) {
  TempFolder folder;
  expect_error(folder.path() / "absent.gltf", {"absent.gltf", "no such file"});
  expect_error(folder.write("broken.gltf", "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [ }"),
               {"broken.gltf", "malformed glTF"});

  {  // mesh 0's second primitive uses vertex 9 of 8
    GltfBuilder gltf;
    const int positions = gltf.add_vec3(std::vector<float>(24, 0.5f));
    const int good = gltf.add_indices_u16({0, 1, 2});
    const int bad = gltf.add_indices_u16({0, 1, 9});
    gltf.json["meshes"].push_back({{"primitives",
                                    {{{"attributes", {{"POSITION", positions}}}, {"indices", good}},
                                     {{"attributes", {{"POSITION", positions}}}, {"indices", bad}}}}});
    gltf.json["nodes"].push_back({{"mesh", 0}});
    expect_error(folder.write("model.gltf", gltf.gltf_text()),
                 {"model.gltf: meshes[0].primitives[1]: index 9 out of range (8 vertices)"});
  }
  {  // an accessor that runs past its bufferView
    GltfBuilder gltf;
    const int positions = gltf.add_vec3(testing::unit_triangle());
    gltf.json["accessors"][positions]["count"] = 4;
    gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}});
    expect_error(folder.write("short.gltf", gltf.gltf_text()),
                 {"short.gltf", "meshes[0].primitives[0].attributes.POSITION", "accessors[0]", "bufferViews[0] has 36 bytes"});
  }
  {  // a NaN position
    GltfBuilder gltf;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3({0, 0, 0, 1, nan, 0, 0, 1, 0})}}}});
    expect_error(folder.write("nan.gltf", gltf.gltf_text()),
                 {"nan.gltf: meshes[0].primitives[0].attributes.POSITION: vertex 1 is not finite"});
  }
  {  // POSITION of the wrong type
    GltfBuilder gltf;
    gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec2({0, 0, 1, 0, 0, 1})}}}});
    expect_error(folder.write("flat.gltf", gltf.gltf_text()), {"flat.gltf", "POSITION", "expected a VEC3 accessor"});
  }
  {  // only points: nothing to render
    GltfBuilder gltf;
    gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}, {"mode", 0}});
    ScopedLogCapture log;
    expect_error(folder.write("points.gltf", gltf.gltf_text()), {"points.gltf", "empty"});
  }
  {  // a node cycle
    GltfBuilder gltf;
    gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}}, {{"children", {1}}});
    gltf.json["nodes"].push_back({{"children", {0}}});
    gltf.json["scenes"] = json::array({{{"nodes", {0}}}});
    gltf.json["scene"] = 0;
    expect_error(folder.write("cycle.gltf", gltf.gltf_text()), {"cycle.gltf", "cycle"});
  }
}

}  // namespace
}  // namespace glint
