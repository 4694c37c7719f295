// G-buffer contents against analytic geometry: ray/plane positions, normals, material colours,
// textures by layer, ids, depth and background.
#include "gl/gl_test_context.h"
#include "raster_test_scene.h"
#include "render/raster_pipeline.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

using render::RasterOutput;
using render::RasterPipeline;
using testing::add_material;
using testing::add_quad;
using testing::hit_quad;
using testing::pixel_ray;
using GBufferPass = testing::GlTest;

constexpr int kSize = 64;
const vec3 kEye(0.0f, 0.0f, 0.0f);

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

TEST_F(GBufferPass, QuadFacingTheCameraMatchesTheAnalyticPlane) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  add_material(scene, vec3(0.5f));  // unused: the quad's material is index 1, so its id must be 2
  const std::uint32_t red = add_material(scene, vec3(0.8f, 0.1f, 0.1f), 0.5f);
  const vec3 origin(-2.0f, -1.5f, -5.0f), edge_u(4.0f, 0.0f, 0.0f), edge_v(0.0f, 3.0f, 0.0f);
  add_quad(scene, origin, edge_u, edge_v, red);
  RasterPipeline raster(scene, kSize, kSize);
  raster.render(testing::look_at(kEye, vec3(0.0f, 0.0f, -1.0f), scene.light.position));

  const ImageRgbaF albedo = raster.read_rgbaf(RasterOutput::AlbedoReflectivity);
  const ImageRgbaF position = raster.read_rgbaf(RasterOutput::WorldPosition);
  const ImageRgbaF normal = raster.read_rgbaf(RasterOutput::WorldNormalRoughness);
  const ImageRgbaF id = raster.read_rgbaf(RasterOutput::MaterialId);
  const ImageRgbaF depth = raster.read_rgbaf(RasterOutput::Depth);
  const render::FrameConstants& constants = raster.frame_constants();

  // Pixels clearly inside a quad shrunk by 0.2 (about two pixels here), or clearly outside one grown
  // by 0.2; the rasterizer decides the edge pixels in between.
  const vec3 margin(0.2f, 0.2f, 0.0f);
  int inside = 0, outside = 0;
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const vec3 ray = pixel_ray(constants, x, y);
      const auto hit = hit_quad(kEye, ray, origin + margin, edge_u - 2.0f * vec3(margin.x, 0, 0),
                                edge_v - 2.0f * vec3(0, margin.y, 0));
      const auto near_hit = hit_quad(kEye, ray, origin - margin, edge_u + 2.0f * vec3(margin.x, 0, 0),
                                     edge_v + 2.0f * vec3(0, margin.y, 0));
      SCOPED_TRACE(::testing::Message() << "pixel (" << x << ", " << y << ")");
      if (hit) {
        ++inside;
        const vec4 p = position.at(x, y);
        ASSERT_LE(glm::length(vec3(p) - *hit), 1e-3f * glm::length(*hit));
        ASSERT_EQ(p.w, 1.0f);
        ASSERT_NEAR(normal.at(x, y).x, 0.0f, 1e-3f);
        ASSERT_NEAR(normal.at(x, y).y, 0.0f, 1e-3f);
        ASSERT_NEAR(normal.at(x, y).z, 1.0f, 1e-3f);
        ASSERT_NEAR(normal.at(x, y).w, 0.25f, 1e-3f);  // roughness
        ASSERT_NEAR(albedo.at(x, y).x, 0.8f, 0.5f / 255.0f + 1e-4f);
        ASSERT_NEAR(albedo.at(x, y).y, 0.1f, 0.5f / 255.0f + 1e-4f);
        ASSERT_NEAR(albedo.at(x, y).z, 0.1f, 0.5f / 255.0f + 1e-4f);
        ASSERT_NEAR(albedo.at(x, y).w, 0.5f, 0.5f / 255.0f + 1e-4f);  // reflectivity
        ASSERT_EQ(id.at(x, y).x, 2.0f);
        const vec4 clip = constants.view_projection * vec4(*hit, 1.0f);
        ASSERT_NEAR(depth.at(x, y).x, 0.5f * clip.z / clip.w + 0.5f, 1e-5f);
      } else if (!near_hit) {
        ++outside;
        ASSERT_EQ(position.at(x, y), vec4(0.0f));
        ASSERT_EQ(id.at(x, y).x, 0.0f);
        ASSERT_EQ(albedo.at(x, y), vec4(0.0f));
        ASSERT_EQ(depth.at(x, y).x, 1.0f);
      }
    }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 300);
}

// A texture of four colour blocks (rows top first: red green / blue white, each block 4x4 texels)
// on a quad with uv (0,0) at its bottom left: each quadrant of the quad shows its block's colour, so
// the texture is neither flipped nor mirrored, and the texels' sRGB values arrive linear. Blocks
// rather than single texels because llvmpipe's anisotropic filter blurs about half a texel even when
// magnifying; block centres are two texels from any other colour.
TEST_F(GBufferPass, TextureAppearsUprightInEachQuadrant) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  Texture texture;
  texture.name = "quadrants";
  texture.width = texture.height = 8;
  const glm::u8vec4 blocks[2][2] = {{{255, 0, 0, 255}, {0, 255, 0, 255}}, {{0, 0, 255, 255}, {255, 255, 255, 255}}};
  texture.rgba.resize(8 * 8 * 4);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      for (int c = 0; c < 4; ++c) texture.rgba[static_cast<std::size_t>((y * 8 + x) * 4 + c)] = blocks[y / 4][x / 4][c];
  scene.textures.push_back(texture);
  const std::uint32_t textured = add_material(scene, vec3(1.0f), 0.0f, 0);
  const vec3 origin(-2.0f, -2.0f, -5.0f), edge_u(4.0f, 0.0f, 0.0f), edge_v(0.0f, 4.0f, 0.0f);
  add_quad(scene, origin, edge_u, edge_v, textured);
  RasterPipeline raster(scene, kSize, kSize);
  raster.render(testing::look_at(kEye, vec3(0.0f, 0.0f, -1.0f), scene.light.position));
  const ImageRgbaF albedo = raster.read_rgbaf(RasterOutput::AlbedoReflectivity);

  struct Quadrant {
    vec2 uv;
    vec3 colour;
  };
  const Quadrant quadrants[] = {{{0.25f, 0.75f}, {1, 0, 0}}, {{0.75f, 0.75f}, {0, 1, 0}},
                                {{0.25f, 0.25f}, {0, 0, 1}}, {{0.75f, 0.25f}, {1, 1, 1}}};
  for (const Quadrant& quadrant : quadrants) {
    // The pixel whose centre sees the texel's centre most closely (bilinear weight ~1 there).
    const vec3 target = origin + quadrant.uv.x * edge_u + quadrant.uv.y * edge_v;
    int best_x = 0, best_y = 0;
    float best = 1e9f;
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const auto hit = hit_quad(kEye, pixel_ray(raster.frame_constants(), x, y), origin, edge_u, edge_v);
        if (hit && glm::length(*hit - target) < best) best = glm::length(*hit - target), best_x = x, best_y = y;
      }
    const vec4 got = albedo.at(best_x, best_y);
    SCOPED_TRACE(::testing::Message() << "uv (" << quadrant.uv.x << ", " << quadrant.uv.y << ") at pixel (" << best_x
                                      << ", " << best_y << ")");
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], quadrant.colour[c], 1.0f / 255.0f);
  }
}

// Two textures of different sizes become layers of one array (resampled to the larger, 8x8): each
// quad shows its own texture's colour, sRGB-decoded (128 -> 0.216, not 0.5).
TEST_F(GBufferPass, MaterialsSampleTheirOwnLayerOfTheTextureArray) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  const auto uniform_texture = [](int width, int height, glm::u8vec4 colour) {
    Texture texture;
    texture.name = "uniform";
    texture.width = width;
    texture.height = height;
    texture.rgba.resize(static_cast<std::size_t>(width * height) * 4);
    for (std::size_t i = 0; i < texture.rgba.size(); ++i) texture.rgba[i] = colour[static_cast<int>(i % 4)];
    return texture;
  };
  scene.textures.push_back(uniform_texture(2, 2, {0, 128, 0, 255}));
  scene.textures.push_back(uniform_texture(8, 4, {0, 0, 128, 255}));
  const std::uint32_t green = add_material(scene, vec3(1.0f), 0.0f, 0);
  const std::uint32_t blue = add_material(scene, vec3(0.5f, 1.0f, 1.0f), 0.0f, 1);
  add_quad(scene, vec3(-2.0f, -1.0f, -5.0f), vec3(1.8f, 0.0f, 0.0f), vec3(0.0f, 2.0f, 0.0f), green);
  add_quad(scene, vec3(0.2f, -1.0f, -5.0f), vec3(1.8f, 0.0f, 0.0f), vec3(0.0f, 2.0f, 0.0f), blue);
  RasterPipeline raster(scene, kSize, kSize);
  EXPECT_EQ(raster.gpu_scene().texture_layer_size(), 8);
  EXPECT_EQ(raster.gpu_scene().texture_layer_count(), 2);
  raster.render(testing::look_at(kEye, vec3(0.0f, 0.0f, -1.0f), scene.light.position));
  const ImageRgbaF albedo = raster.read_rgbaf(RasterOutput::AlbedoReflectivity);
  const float half = srgb_to_linear(128.0f / 255.0f);
  const vec4 left = albedo.at(kSize / 2 - 8, kSize / 2), right = albedo.at(kSize / 2 + 8, kSize / 2);
  const float tolerance = 2.0f / 255.0f;
  EXPECT_NEAR(left.x, 0.0f, tolerance);
  EXPECT_NEAR(left.y, half, tolerance);
  EXPECT_NEAR(left.z, 0.0f, tolerance);
  EXPECT_NEAR(right.x, 0.0f, tolerance);
  EXPECT_NEAR(right.y, 0.0f, tolerance);
  EXPECT_NEAR(right.z, half, tolerance);
}

// Back faces are drawn (scenes are open): a quad facing away from the camera still fills the
// G-buffer, with its authored normal (pointing away), not one flipped towards the viewer.
TEST_F(GBufferPass, BackFacesAreDrawnWithTheirAuthoredNormal) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  const std::uint32_t grey = add_material(scene, vec3(0.5f));
  add_quad(scene, vec3(2.0f, -2.0f, -5.0f), vec3(-4.0f, 0.0f, 0.0f), vec3(0.0f, 4.0f, 0.0f), grey);  // normal -z
  RasterPipeline raster(scene, kSize, kSize);
  raster.render(testing::look_at(kEye, vec3(0.0f, 0.0f, -1.0f), scene.light.position));
  const vec4 n = raster.read_rgbaf(RasterOutput::WorldNormalRoughness).at(kSize / 2, kSize / 2);
  EXPECT_NEAR(n.z, -1.0f, 1e-3f);
  EXPECT_EQ(raster.read_rgbaf(RasterOutput::MaterialId).at(kSize / 2, kSize / 2).x, 1.0f);
}

}  // namespace
}  // namespace glint
