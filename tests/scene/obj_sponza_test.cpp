// The real Dabrovic Sponza from the shared assets folder (not part of the repository): skipped with
// a message when it is absent.
#include "scene/obj_loader.h"

#include "core/log.h"

#include <gtest/gtest.h>

#include "support/test_paths.h"

#include <cstdlib>
#include <filesystem>
#include <set>

namespace glint {
namespace {

std::filesystem::path sponza_path() {
  const char* assets = std::getenv("GLINT_ASSETS");
  const std::filesystem::path folder = assets != nullptr && *assets != '\0'
                                           ? std::filesystem::path(assets)
                                           : testing::source_dir() / ".." / "shared" / "assets";
  return folder / "sponza_dabrovic" / "sponza.obj";
}

TEST(ObjSponza, LoadsTheDabrovicAtriumCompletely) {
  const std::filesystem::path path = sponza_path();
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent (set GLINT_ASSETS to the assets folder)";
  ScopedLogCapture capture;
  const Scene scene = load_obj(path);

  EXPECT_EQ(capture.count_warnings(""), 0);  // in particular no degenerate triangles and no missing textures
  EXPECT_EQ(scene.name, "sponza");
  // 37 `o` objects with one `usemtl` each. The file has 66,350 `v` lines (the assets README's count)
  // but 14 are used by no face; every face corner has its own index triple, so the meshes hold
  // 66,336 vertices. All 66,445 faces are triangles with non-zero area (checked independently).
  EXPECT_EQ(scene.meshes.size(), 37u);
  EXPECT_EQ(scene.vertex_count(), 66336u);
  EXPECT_EQ(scene.triangle_count(), 66445u);
  EXPECT_EQ(scene.materials.size(), 19u);  // all 19 of sponza.mtl are used; no "default" needed
  for (const Material& material : scene.materials) EXPECT_NE(material.name, "default");

  // 17 materials have a map_Kd naming 10 distinct JPGs, each loaded once, none a placeholder.
  int textured = 0;
  std::set<int> texture_indices;
  for (const Material& material : scene.materials) {
    if (material.diffuse_texture < 0) continue;
    ++textured;
    texture_indices.insert(material.diffuse_texture);
    const Texture& texture = scene.textures[static_cast<std::size_t>(material.diffuse_texture)];
    EXPECT_FALSE(texture.placeholder) << material.name << ": " << texture.name;
    EXPECT_GT(texture.width, 0) << texture.name;
    EXPECT_EQ(texture.rgba.size(), static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height) * 4);
  }
  EXPECT_EQ(textured, 17);
  EXPECT_EQ(scene.textures.size(), 10u);
  EXPECT_EQ(texture_indices.size(), 10u);

  // Bounds from the assets README: x -17.4..17.4, y -0.9..15.7, z -7.8..7.8.
  const Aabb bounds = scene.world_bounds();
  EXPECT_NEAR(bounds.min.x, -17.4f, 0.1f);
  EXPECT_NEAR(bounds.max.x, 17.4f, 0.1f);
  EXPECT_NEAR(bounds.max.y, 15.7f, 0.1f);
  for (const Mesh& mesh : scene.meshes) {
    EXPECT_EQ(mesh.uvs.size(), mesh.vertex_count()) << mesh.name;  // the file has UVs everywhere
    EXPECT_EQ(mesh.normals.size(), mesh.vertex_count()) << mesh.name;
  }
}

}  // namespace
}  // namespace glint
