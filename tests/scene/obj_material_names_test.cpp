// Material names with blanks ("newmtl 01 - Default", as 3ds Max names them): `newmtl` and `usemtl`
// read the whole rest of the line. Both read the first word before, so "01 - Default" and "01 - Glass"
// were one material "01" (defined twice, the first kept) and every face got the first one's colour.
#include "scene/obj_loader.h"

#include "core/log.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace glint {
namespace {

TEST(ObjMaterialNames, NamesWithBlanksStayApart) {
  testing::TempFolder folder;
  folder.write("m.mtl", "newmtl 01 - Default\nKd 1 0 0\nnewmtl 01 - Glass  \nKd 0 1 0\n");
  const auto obj = folder.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                         "usemtl 01 - Default\nf 1 2 3\nusemtl 01 - Glass\nf 2 4 3\nusemtl 01 - Default\nf 1 3 2\n");
  const ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  for (const auto& entry : capture.entries()) EXPECT_NE(entry.level, LogLevel::warning) << entry.message;
  ASSERT_EQ(scene.meshes.size(), 2u);
  for (const Mesh& mesh : scene.meshes) {
    const Material& material = scene.materials.at(mesh.material);
    if (material.name == "01 - Default") {
      EXPECT_EQ(material.diffuse, vec3(1, 0, 0));
      EXPECT_EQ(mesh.triangle_count(), 2u);
    } else {
      EXPECT_EQ(material.name, "01 - Glass");  // trailing blanks are not part of the name
      EXPECT_EQ(material.diffuse, vec3(0, 1, 0));
      EXPECT_EQ(mesh.triangle_count(), 1u);
    }
  }
}

TEST(ObjMaterialNames, AnUndefinedNameWithBlanksIsNamedWhole) {
  testing::TempFolder folder;
  folder.write("m.mtl", "newmtl Mat\nKd 1 0 0\n");
  const auto obj = folder.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Mat Two\nf 1 2 3\n");
  const ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  const bool warned = std::any_of(capture.entries().begin(), capture.entries().end(), [](const auto& entry) {
    return entry.message.find("material 'Mat Two' is not defined in any material library") != std::string::npos;
  });
  EXPECT_TRUE(warned);
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_NE(scene.materials.at(scene.meshes[0].material).diffuse, vec3(1, 0, 0)) << "not 'Mat''s colour";
}

}  // namespace
}  // namespace glint
