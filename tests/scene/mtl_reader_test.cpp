// The MTL reader on its own (suite names start with "Obj" so that the loader's test filter runs them).
#include "scene/mtl_reader.h"

#include "core/error.h"
#include "core/log.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(ObjMtlReader, TextureFileNameSkipsOptionsAndKeepsSpaces) {
  EXPECT_EQ(texture_file_name("wall.png"), "wall.png");
  EXPECT_EQ(texture_file_name("  -s 1 1 1 -o 0.5 tex/wall.png "), "tex/wall.png");
  EXPECT_EQ(texture_file_name("-s 2 tex/wall.png"), "tex/wall.png");  // -s with one number
  EXPECT_EQ(texture_file_name("-bm 0.5 -clamp on -blendu off my wall.jpg"), "my wall.jpg");
  EXPECT_EQ(texture_file_name("-imfchan r -mm 0 1 -texres 512 -type sphere -boost 2 -t 1 2 3 a.tga"), "a.tga");
  EXPECT_EQ(texture_file_name("-clamp on"), "");
}

TEST(ObjMtlReader, ReadsEveryMaterialInOrderWithLinesAndTextures) {
  const std::vector<MtlMaterial> materials = read_mtl_text(
      "# two\nnewmtl first\n\tKd 0.25 0.5 1\r\n  map_Kd -s 2 2 2 textures\\A.png\nnewmtl second\nPr 3\nPm -1\nNs 5\n"
      "Ka spectral ident.rfl\nKs xyz 0.1 0.2 0.3\nd -halo 0.5\nillum 2\nmap_Bump whatever -bm 1\n",
      "test.mtl");
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_EQ(materials[0].material.name, "first");
  EXPECT_EQ(materials[0].line, 2u);
  EXPECT_EQ(materials[0].material.diffuse, vec3(0.25f, 0.5f, 1.0f));
  EXPECT_EQ(materials[0].diffuse_map, "textures\\A.png");
  EXPECT_EQ(materials[0].diffuse_map_line, 4u);
  EXPECT_EQ(materials[1].material.roughness, 1.0f);     // clamped
  EXPECT_EQ(materials[1].material.reflectivity, 0.0f);  // clamped
  EXPECT_EQ(materials[1].material.specular_exponent, 5.0f);
  EXPECT_EQ(materials[1].material.specular, vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(materials[1].material.diffuse, Material{}.diffuse);  // no Kd: the default
  EXPECT_TRUE(materials[1].diffuse_map.empty());
}

TEST(ObjMtlReader, DuplicateNameKeepsTheFirstDefinitionWithAWarning) {
  ScopedLogCapture capture;
  const std::vector<MtlMaterial> materials =
      read_mtl_text("newmtl a\nKd 1 0 0\nnewmtl a\nKd 0 1 0\nnewmtl b\n", "dup.mtl");
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_EQ(materials[0].material.diffuse, vec3(1, 0, 0));
  EXPECT_EQ(materials[1].material.name, "b");
  EXPECT_EQ(capture.count_warnings("dup.mtl:3:"), 1);
}

TEST(ObjMtlReader, MalformedStatementsNameTheLine) {
  struct Case {
    const char* text;
    const char* expected;
  };
  for (const Case& bad : {Case{"newmtl a\nKd 1 2\n", "x.mtl:2: 'Kd' has 2 numbers"},
                          Case{"newmtl a\nKs\n", "x.mtl:2: 'Ks' needs 3 numbers"},
                          Case{"newmtl a\nKe 1 2 3 4\n", "x.mtl:2: 'Ke' has more than 3"},
                          Case{"newmtl a\n\nNs high\n", "x.mtl:3: 'Ns': 'high' is not a number"},
                          Case{"newmtl a\nNs 1 2\n", "x.mtl:2: 'Ns' takes one number"},
                          Case{"newmtl a\nPm nan\n", "x.mtl:2: 'Pm': 'nan' is not a finite number"},
                          Case{"newmtl\n", "x.mtl:1: 'newmtl' needs a material name"},
                          Case{"newmtl a\nmap_Kd -s 1 1 1\n", "x.mtl:2: 'map_Kd' needs a file name"},
                          Case{"Kd 1 1 1\n", "x.mtl:1: 'Kd' before any 'newmtl'"}}) {
    try {
      read_mtl_text(bad.text, "x.mtl");
      ADD_FAILURE() << "no error for: " << bad.text;
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find(bad.expected), std::string::npos) << error.what();
    }
  }
}

}  // namespace
}  // namespace glint
