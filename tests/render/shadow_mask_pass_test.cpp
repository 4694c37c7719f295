// The shadow mask against the analytic shadow: a floor under a floating lid and beside a wall that
// stands on it, every floor pixel checked by casting its own ray to the light on the CPU.
#include "gl/gl_test_context.h"
#include "raster_test_scene.h"
#include "render/raster_pipeline.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

using render::RasterOutput;
using render::RasterPipeline;
using ShadowMaskPass = testing::GlTest;

constexpr int kSize = 96;

struct ShadowCheck {
  int lit_checked = 0, shadowed_checked = 0, wrong = 0;
};

// Which pixels check_against_analytic_shadow checks: those at least 2 pixels inside the image, or
// the image's outermost rows and columns.
enum class CheckedPixels { interior, border };

// Floor pixels whose 5x5 neighbourhood is all floor with the same expected answer must match it
// exactly (1 lit: no acne anywhere on the floor; 0 shadowed); pixels within 2 of a shadow boundary
// or another surface are left to PCF. On the border only the neighbours inside the image count.
ShadowCheck check_against_analytic_shadow(const RasterPipeline& raster, vec3 light,
                                          const std::vector<testing::QuadGeometry>& occluders,
                                          CheckedPixels checked = CheckedPixels::interior) {
  const ImageRgbaF position = raster.read_rgbaf(RasterOutput::WorldPosition);
  const ImageRgbaF id = raster.read_rgbaf(RasterOutput::MaterialId);
  const ImageRgbaF mask = raster.read_rgbaf(RasterOutput::ShadowMask);
  const int w = raster.width(), h = raster.height();
  Image<int> expected(w, h, -1);  // -1 not floor, else 1 lit / 0 shadowed
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (id.at(x, y).x == 1.0f) expected.at(x, y) = testing::light_blocked(vec3(position.at(x, y)), light, occluders) ? 0 : 1;
  ShadowCheck check;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool interior = x >= 2 && x < w - 2 && y >= 2 && y < h - 2;
      const bool border = x == 0 || x == w - 1 || y == 0 || y == h - 1;
      if (!(checked == CheckedPixels::interior ? interior : border)) continue;
      const int e = expected.at(x, y);
      if (e < 0) continue;
      bool uniform = true;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int nx = x + dx, ny = y + dy;
          if (nx >= 0 && nx < w && ny >= 0 && ny < h) uniform = uniform && expected.at(nx, ny) == e;
        }
      if (!uniform) continue;
      (e == 1 ? check.lit_checked : check.shadowed_checked) += 1;
      if (mask.at(x, y).x != static_cast<float>(e)) {
        if (++check.wrong <= 5)
          ADD_FAILURE() << "pixel (" << x << ", " << y << ") mask " << mask.at(x, y).x << ", expected " << e;
      }
    }
  return check;
}

TEST_F(ShadowMaskPass, FloorShadowIsTheAnalyticProjectionOfTheOccluders) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  RasterPipeline raster(scene, kSize, kSize);
  raster.render(testing::look_at(vec3(0.0f, 9.0f, 9.0f), vec3(0.0f, 0.0f, 0.0f), scene.light.position));
  const ShadowCheck check = check_against_analytic_shadow(raster, scene.light.position, occluders);
  EXPECT_EQ(check.wrong, 0);
  EXPECT_GT(check.shadowed_checked, 150);  // both shadows are well inside the view
  EXPECT_GT(check.lit_checked, 3000);
}

// Without PCF the same must hold (one sample, hard edges), and with a coarse 256 map the bias must
// still keep the lit floor free of acne.
TEST_F(ShadowMaskPass, HoldsWithoutPcfAndWithACoarseMap) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  for (const auto& [size, pcf] : {std::pair{1024, 0.0f}, std::pair{256, 1.5f}}) {
    SCOPED_TRACE(::testing::Message() << "map " << size << ", PCF radius " << pcf);
    render::RasterSettings settings;
    settings.shadow_map_size = size;
    settings.pcf_radius_texels = pcf;
    RasterPipeline raster(scene, kSize, kSize, settings);
    raster.render(testing::look_at(vec3(0.0f, 9.0f, 9.0f), vec3(0.0f, 0.0f, 0.0f), scene.light.position));
    const ShadowCheck check = check_against_analytic_shadow(raster, scene.light.position, occluders);
    EXPECT_EQ(check.wrong, 0);
    EXPECT_GT(check.shadowed_checked, 150);
  }
}

// A light moved between frames moves the shadow (the cube map is re-rendered each frame): from
// straight above the lid to beside it.
TEST_F(ShadowMaskPass, ShadowFollowsTheLight) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  RasterPipeline raster(scene, kSize, kSize);
  const vec3 moved(-3.0f, 5.0f, 1.0f);
  raster.render(testing::look_at(vec3(0.0f, 9.0f, 9.0f), vec3(0.0f, 0.0f, 0.0f), scene.light.position));
  raster.render(testing::look_at(vec3(0.0f, 9.0f, 9.0f), vec3(0.0f, 0.0f, 0.0f), moved));
  const ShadowCheck check = check_against_analytic_shadow(raster, moved, occluders);
  EXPECT_EQ(check.wrong, 0);
  EXPECT_GT(check.shadowed_checked, 100);
}

// 37 x 23 is no multiple of the pass's 8 x 8 work groups: the partial groups at the right and top
// must write every pixel of the last column and row, each with its own pixel's answer. The camera
// looks almost straight down at the corner (2, 0, 2) of the lid's shadow, from beside the lid, so
// that the border crosses the shadow's edges (read-backs are top row first; the whole border is
// checked).
TEST_F(ShadowMaskPass, TheBorderOfAnImageOfPartialWorkGroupsIsTheAnalyticShadow) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  RasterPipeline raster(scene, 37, 23);
  raster.render(testing::look_at(vec3(2.5f, 3.0f, 2.0f), vec3(2.0f, 0.0f, 2.0f), scene.light.position));
  const ShadowCheck check =
      check_against_analytic_shadow(raster, scene.light.position, occluders, CheckedPixels::border);
  EXPECT_EQ(check.wrong, 0);
  EXPECT_GT(check.shadowed_checked, 10);
  EXPECT_GT(check.lit_checked, 10);
}

}  // namespace
}  // namespace glint
