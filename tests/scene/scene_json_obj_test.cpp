// Scene files over OBJ meshes: the features that depend on OBJ specifics (materials by MTL name,
// files that split into several meshes, map_Kd textures, OBJ errors inside a scene file).
#include "core/error.h"
#include "scene/scene_json_loader.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

using testing::TempFolder;

// Two quads in one object, one per material; "stone" is textured by a file the test does not write,
// so it gets the checker placeholder (a warning, not an error).
void write_two_material_obj(const TempFolder& folder) {
  folder.write("mesh/room.mtl",
               "newmtl floor_tiles\nKd 0.5 0.5 0.5\n\nnewmtl stone\nKd 0.8 0.7 0.6\nmap_Kd stone.png\n");
  folder.write("mesh/room.obj",
               "mtllib room.mtl\no room\n"
               "v 0 0 0\nv 4 0 0\nv 4 0 4\nv 0 0 4\n"
               "v 0 0 0\nv 4 0 0\nv 4 3 0\nv 0 3 0\n"
               "usemtl floor_tiles\nf 1 4 3\nf 1 3 2\n"
               "usemtl stone\nf 5 6 7\nf 5 7 8\n");
}

const Material& material_named(const Scene& scene, const std::string& name) {
  for (const Material& material : scene.materials)
    if (material.name.find(name) != std::string::npos) return material;
  ADD_FAILURE() << "no material named " << name;
  return scene.materials.front();
}

TEST(SceneJsonObj, FloorByMtlNameOverridesDeformOnASplitFileAndSharedStaticCopies) {
  TempFolder folder;
  write_two_material_obj(folder);
  const auto scene_file = folder.write("gallery.scene.json", R"({
    "meshes": [
      { "file": "mesh/room.obj", "name": "left" },
      { "file": "mesh/room.obj", "name": "right", "transform": { "translate": [10, 0, 0] } },
      { "file": "mesh/room.obj", "name": "wobbly", "transform": { "translate": [20, 0, 0] },
        "material": { "reflectivity": 0.25 },
        "deform": { "type": "sine", "axis": "y", "along": "x", "amplitude": 0.1, "frequency": 2, "speed": 1 } }
    ],
    "floor": { "materials": ["floor_tiles"], "reflectivity": 0.6 },
    "camera": { "path": [[1, 1.7, 1], [3, 1.7, 3]] }
  })");
  const Scene scene = load_scene_json(scene_file);

  // The OBJ splits into two meshes per entry; the two static entries share theirs, the deformable
  // entry has its own two (they deform independently of the static copies).
  EXPECT_EQ(scene.instances.size(), 6u);
  EXPECT_EQ(scene.meshes.size(), 4u);
  int deformable = 0;
  for (const Mesh& mesh : scene.meshes) {
    if (!mesh.deformable) continue;
    ++deformable;
    ASSERT_TRUE(mesh.deform.has_value());
    EXPECT_EQ(mesh.deform->displace_axis, 1);
    EXPECT_EQ(mesh.deform->wave_axis, 0);
    EXPECT_FLOAT_EQ(mesh.deform->amplitude, 0.1f);
  }
  EXPECT_EQ(deformable, 2);

  // Floor reflectivity found by the MTL's material name; the override reaches the wobbly entry only.
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    const Material& material = scene.materials[mesh.material];
    const bool is_floor = material.name.find("floor_tiles") != std::string::npos;
    const bool is_wobbly = instance.name.find("wobbly") != std::string::npos;
    const float expected = is_wobbly && !is_floor ? 0.25f : is_floor ? 0.6f : 0.0f;
    EXPECT_FLOAT_EQ(material.reflectivity, expected) << instance.name << " / " << material.name;
  }
  // The missing map_Kd became a placeholder texture that the re-indexed material still points at.
  const Material& stone = material_named(scene, "stone");
  ASSERT_GE(stone.diffuse_texture, 0);
  EXPECT_TRUE(scene.textures[static_cast<std::size_t>(stone.diffuse_texture)].placeholder);
  EXPECT_NEAR(scene.world_bounds().max.x, 24.0f, 1e-5f);
}

TEST(SceneJsonObj, AnObjErrorInsideASceneNamesTheJsonEntryAndTheObjLine) {
  TempFolder folder;
  folder.write("broken.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  const auto scene_file = folder.write("s.scene.json", R"({ "meshes": [ { "file": "broken.obj" } ] })");
  std::string message;
  try {
    load_scene_json(scene_file);
  } catch (const Error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("/meshes/0"), std::string::npos) << message;
  EXPECT_NE(message.find("broken.obj:4"), std::string::npos) << message;
}

}  // namespace
}  // namespace glint
