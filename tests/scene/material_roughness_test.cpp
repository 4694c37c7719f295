// Where a material's roughness (the width of its glossy reflection, docs/glossy.md) comes from in
// each loader: MTL Pr, else Ns through specular_roughness.h; glTF roughnessFactor; a scene file's
// "roughness" override; the atrium's range of finishes.
#include "scene/gltf_loader.h"
#include "scene/gltf_test_builder.h"
#include "scene/mtl_reader.h"
#include "scene/obj_loader.h"
#include "scene/procedural/atrium.h"
#include "scene/scene_json_loader.h"
#include "scene/specular_roughness.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace glint {
namespace {

using testing::GltfBuilder;
using testing::TempFolder;

float mtl_roughness(const std::string& statements) {
  const std::vector<MtlMaterial> materials = read_mtl_text("newmtl m\n" + statements, "x.mtl");
  EXPECT_EQ(materials.size(), 1u);
  return materials.empty() ? -1.0f : materials.front().material.roughness;
}

const Material& material_named(const Scene& scene, const std::string& name) {
  const auto found = std::find_if(scene.materials.begin(), scene.materials.end(),
                                  [&](const Material& m) { return m.name == name; });
  if (found == scene.materials.end()) throw std::runtime_error("no material " + name);
  return *found;
}

TEST(SpecularRoughness, ExponentAndRoughnessInvertEachOtherInsideTheClamp) {
  for (float roughness : {0.2f, 0.35f, 0.5f, 0.75f, 0.9f})
    EXPECT_NEAR(roughness_from_specular_exponent(specular_exponent_from_roughness(roughness)), roughness, 1e-4f) << roughness;
  EXPECT_FLOAT_EQ(roughness_from_specular_exponent(30.0f), 0.5f);
  EXPECT_FLOAT_EQ(roughness_from_specular_exponent(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(roughness_from_specular_exponent(-3.0f), 1.0f);
  EXPECT_GT(roughness_from_specular_exponent(10.0f), roughness_from_specular_exponent(500.0f));
}

TEST(ObjMtlRoughness, PrWinsElseNsElseAMirror) {
  EXPECT_FLOAT_EQ(mtl_roughness("Pr 0.3\nNs 500\n"), 0.3f);
  EXPECT_FLOAT_EQ(mtl_roughness("Ns 500\nPr 0.3\n"), 0.3f) << "in any order";
  EXPECT_FLOAT_EQ(mtl_roughness("Pr 0\nNs 10\n"), 0.0f) << "an explicit Pr 0 is a mirror";
  EXPECT_FLOAT_EQ(mtl_roughness("Ns 30\n"), 0.5f) << "Ns alone: the GGX lobe of its width";
  EXPECT_FLOAT_EQ(mtl_roughness("Ns 30\n"), roughness_from_specular_exponent(30.0f));
  EXPECT_FLOAT_EQ(mtl_roughness("Kd 1 1 1\n"), 0.0f) << "neither: a mirror, as before glossy reflections";
  EXPECT_FLOAT_EQ(mtl_roughness("Pr 4\n"), 1.0f) << "clamped";
}

TEST(ObjMtlRoughness, TheObjLoaderKeepsTheMtlRoughness) {
  TempFolder folder;
  folder.write("m.mtl", "newmtl glossy\nNs 30\nnewmtl rough\nPr 0.8\n");
  const auto obj = folder.write("q.obj",
                                "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "usemtl glossy\nf 1 2 3\nusemtl rough\nf 1 3 4\n");
  const Scene scene = load_obj(obj);
  EXPECT_FLOAT_EQ(material_named(scene, "glossy").roughness, 0.5f);
  EXPECT_FLOAT_EQ(material_named(scene, "rough").roughness, 0.8f);
}

TEST(GltfRoughness, RoughnessFactorBecomesTheRoughness) {
  GltfBuilder gltf;
  const int positions = gltf.add_vec3({0, 0, 0, 1, 0, 0, 0, 1, 0});
  gltf.json["materials"].push_back(
      {{"name", "satin"}, {"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.4}}}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}, {"material", 0}});
  gltf.add_mesh_node({{"attributes", {{"POSITION", positions}}}});  // glTF's default material: roughness 1
  TempFolder folder;
  const Scene scene = load_gltf(folder.write("m.gltf", gltf.gltf_text()));
  EXPECT_FLOAT_EQ(scene.materials[scene.meshes[0].material].roughness, 0.4f);
  EXPECT_FLOAT_EQ(scene.materials[scene.meshes[1].material].roughness, 1.0f);
}

TEST(SceneJsonRoughness, TheMaterialOverrideSetsTheRoughness) {
  TempFolder folder;
  folder.write("m.mtl", "newmtl glossy\nNs 30\n");
  folder.write("q.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl glossy\nf 1 2 3\n");
  const Scene scene = load_scene_json_text(
      R"({"meshes": [{"file": "q.obj", "name": "a", "material": {"roughness": 0.125}}, {"file": "q.obj", "name": "b"}]})",
      folder.path() / "r.scene.json");
  ASSERT_EQ(scene.instances.size(), 2u);
  EXPECT_FLOAT_EQ(scene.materials[scene.meshes[scene.instances[0].mesh].material].roughness, 0.125f);
  EXPECT_FLOAT_EQ(scene.materials[scene.meshes[scene.instances[1].mesh].material].roughness, 0.5f);
}

TEST(AtriumRoughness, TheAtriumHasPolishedMarbleRougherStoneAndMetal) {
  const Scene scene = procedural::make_atrium(procedural::AtriumDetail::simple);
  const Material& marble = material_named(scene, "marble-floor");
  const Material& stone = material_named(scene, "polished-stone");
  const Material& metal = material_named(scene, "bronze");
  for (const Material* m : {&marble, &stone, &metal}) EXPECT_GT(m->reflectivity, 0.0f) << m->name;
  EXPECT_GT(marble.roughness, 0.0f);
  EXPECT_LT(marble.roughness, metal.roughness);
  EXPECT_LT(metal.roughness, stone.roughness);
  // Every reflective material is used by some mesh.
  for (const Material* m : {&marble, &stone, &metal}) {
    const auto index = static_cast<std::uint32_t>(m - scene.materials.data());
    EXPECT_TRUE(std::any_of(scene.meshes.begin(), scene.meshes.end(), [&](const Mesh& mesh) { return mesh.material == index; }))
        << m->name;
  }
}

}  // namespace
}  // namespace glint
