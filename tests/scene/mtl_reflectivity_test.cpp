// How an MTL file makes an OBJ surface a mirror (docs/scene-format.md, "OBJ materials"): Pm, else Km,
// else Ks under the ray-traced reflection models illum 3-7. Suite name starts with "Obj" so that the
// loader's test filter runs it.
#include "scene/mtl_reader.h"

#include "core/log.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace glint {
namespace {

float reflectivity_of(const std::string& statements) {
  const std::vector<MtlMaterial> materials = read_mtl_text("newmtl m\n" + statements, "x.mtl");
  EXPECT_EQ(materials.size(), 1u);
  return materials.empty() ? -1.0f : materials.front().material.reflectivity;
}

TEST(ObjMtlReflectivity, RayTracedReflectionIllumModelsMirrorWithKs) {
  EXPECT_FLOAT_EQ(reflectivity_of("Ks 0.6 0.6 0.6\nillum 3\n"), 0.6f);
  EXPECT_FLOAT_EQ(reflectivity_of("illum 3\nKs 0.2 0.7 0.4\n"), 0.7f) << "the largest component, in any order";
  for (const char* model : {"4", "5", "6", "7"})
    EXPECT_FLOAT_EQ(reflectivity_of(std::string("Ks 0.5 0.5 0.5\nillum ") + model + "\n"), 0.5f) << "illum " << model;
  EXPECT_FLOAT_EQ(reflectivity_of("illum 3\n"), 1.0f) << "illum 3 without Ks: a full mirror";
  EXPECT_FLOAT_EQ(reflectivity_of("Ks 2 2 2\nillum 3\n"), 1.0f) << "clamped";
}

TEST(ObjMtlReflectivity, KsIsOnlyAHighlightOutsideTheReflectionModels) {
  EXPECT_FLOAT_EQ(reflectivity_of("Ks 0.9 0.9 0.9\n"), 0.0f);
  for (const char* model : {"0", "1", "2", "8", "9", "10", "3.5"})
    EXPECT_FLOAT_EQ(reflectivity_of(std::string("Ks 0.9 0.9 0.9\nillum ") + model + "\n"), 0.0f) << "illum " << model;
  const std::vector<MtlMaterial> materials = read_mtl_text("newmtl m\nKs 0.9 0.8 0.7\n", "x.mtl");
  EXPECT_EQ(materials.front().material.specular, vec3(0.9f, 0.8f, 0.7f)) << "Ks stays the highlight colour";
}

TEST(ObjMtlReflectivity, KmAndPmSayItDirectlyAndPmWins) {
  EXPECT_FLOAT_EQ(reflectivity_of("Km 0.3\n"), 0.3f);
  EXPECT_FLOAT_EQ(reflectivity_of("Km 0.3\nKs 1 1 1\nillum 3\n"), 0.3f) << "Km before Ks";
  EXPECT_FLOAT_EQ(reflectivity_of("Pm 0.8\n"), 0.8f);
  EXPECT_FLOAT_EQ(reflectivity_of("Pm 0.8\nKm 0.3\nillum 3\n"), 0.8f) << "Pm before everything";
  EXPECT_FLOAT_EQ(reflectivity_of("Pm 0\nillum 3\n"), 0.0f) << "an explicit Pm 0 is not a mirror";
  EXPECT_FLOAT_EQ(reflectivity_of("Km 1.5\n"), 1.0f) << "clamped";
}

TEST(ObjMtlReflectivity, EachMaterialHasItsOwnStatementsAndDuplicatesDoNotLeak) {
  ScopedLogCapture log;  // the second 'a' is a warning
  const std::vector<MtlMaterial> materials =
      read_mtl_text("newmtl a\nillum 3\nKs 0.4 0.4 0.4\nnewmtl b\nKs 1 1 1\nnewmtl a\nPm 1\n", "x.mtl");
  ASSERT_EQ(materials.size(), 2u);
  EXPECT_FLOAT_EQ(materials[0].material.reflectivity, 0.4f) << "the second 'a' is dropped, its Pm with it";
  EXPECT_FLOAT_EQ(materials[1].material.reflectivity, 0.0f);
}

}  // namespace
}  // namespace glint
