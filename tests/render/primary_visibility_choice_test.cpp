// --primary auto (PrimaryVisibility::automatic): the rule that picks between the id draw and the
// compute rasteriser, what RasterPipeline does with it on a software renderer (the id draw, untimed,
// the compute rasteriser never made) and on a GPU (both timed on the first frame, the loser dropped,
// the winner's ids in the frame), and the GL timing it uses.
#include "gl/gl_renderer.h"
#include "gl/gl_work_time.h"
#include "raster_test_scene.h"
#include "render/primary_visibility_choice.h"
#include "render/raster_pipeline.h"
#include "render/texture_readback.h"
#include "render/visibility_id_pass.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <vector>

namespace glint::render {
namespace {

using PrimaryVisibilityChoiceTest = testing::GlTest;

RasterSettings visibility_settings(PrimaryVisibility primary) {
  RasterSettings settings;
  settings.gbuffer = GBufferMethod::visibility;
  settings.primary = primary;
  return settings;
}

struct Rendered {
  std::vector<glm::uvec2> ids;
  ImageRgbaF albedo;
};

Rendered read(const RasterPipeline& raster) {
  return {read_visibility_ids(raster.visibility_id(), raster.width(), raster.height()),
          raster.read_rgbaf(RasterOutput::AlbedoReflectivity)};
}

TEST(PrimaryVisibilityRule, ComputeOnlyWhenFasterByTheMargin) {
  EXPECT_EQ(faster_primary_visibility(1.16, 0.17), PrimaryVisibility::compute);  // the H100's atrium
  EXPECT_EQ(faster_primary_visibility(0.13, 0.39), PrimaryVisibility::raster);
  EXPECT_EQ(faster_primary_visibility(1.0, 1.0), PrimaryVisibility::raster);
  // Just inside and just outside the margin.
  EXPECT_EQ(faster_primary_visibility(1.0, 0.99 / kComputeRasterMargin), PrimaryVisibility::compute);
  EXPECT_EQ(faster_primary_visibility(1.0, 1.01 / kComputeRasterMargin), PrimaryVisibility::raster);
}

TEST(PrimaryVisibilityRule, AutoIsAName) {
  EXPECT_EQ(parse_primary_visibility("auto"), PrimaryVisibility::automatic);
  EXPECT_EQ(primary_visibility_name(PrimaryVisibility::automatic), "auto");
}

TEST(PrimaryVisibilityRule, OnlySoftwareRenderersChooseUntimed) {
  EXPECT_TRUE(untimed_primary_visibility("llvmpipe (LLVM 15.0.6, 256 bits)").has_value());
  EXPECT_FALSE(untimed_primary_visibility("NVIDIA H100 80GB HBM3/PCIe/SSE2").has_value());
}

TEST(GlRenderer, SoftwareRenderersAreMesasRasterisers) {
  EXPECT_TRUE(software_gl_renderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
  EXPECT_TRUE(software_gl_renderer("softpipe"));
  EXPECT_FALSE(software_gl_renderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
  EXPECT_FALSE(software_gl_renderer(""));
}

TEST_F(PrimaryVisibilityChoiceTest, SoftwareRendererKeepsTheIdDrawUntimed) {
  if (!software_gl_renderer(current_gl_renderer())) GTEST_SKIP() << "a GPU times both (the next test)";
  const std::optional<PrimaryVisibilityChoice> choice = untimed_primary_visibility(current_gl_renderer());
  ASSERT_TRUE(choice.has_value());
  EXPECT_EQ(choice->method, PrimaryVisibility::raster);
  EXPECT_FALSE(choice->raster_ms.has_value());
  EXPECT_FALSE(choice->compute_ms.has_value());

  const Scene scene = testing::mirror_floor_with_wall(-4.0f);
  const FrameState state = testing::camera_looking_down_the_floor();
  RasterPipeline automatic(scene, 96, 64, visibility_settings(PrimaryVisibility::automatic));
  // Decided at construction: the compute rasteriser is never made (nor its shaders compiled).
  EXPECT_EQ(automatic.primary_visibility(), PrimaryVisibility::raster);
  EXPECT_EQ(automatic.compute_visibility(), nullptr);
  automatic.render(state);
  RasterPipeline raster(scene, 96, 64, visibility_settings(PrimaryVisibility::raster));
  raster.render(state);
  const Rendered a = read(automatic), r = read(raster);
  EXPECT_EQ(a.ids, r.ids);
  EXPECT_EQ(a.albedo.pixels, r.albedo.pixels);
}

TEST_F(PrimaryVisibilityChoiceTest, GpuTimesBothOnTheFirstFrameAndKeepsTheFaster) {
  if (software_gl_renderer(current_gl_renderer())) GTEST_SKIP() << "needs a GPU: software renderers are not timed";
  const Scene scene = testing::mirror_floor_with_wall(-4.0f);
  const FrameState state = testing::camera_looking_down_the_floor();
  RasterPipeline automatic(scene, 320, 192, visibility_settings(PrimaryVisibility::automatic));
  EXPECT_EQ(automatic.primary_visibility(), PrimaryVisibility::automatic);  // not chosen before a frame
  EXPECT_NE(automatic.compute_visibility(), nullptr);
  automatic.render(state);
  const std::optional<PrimaryVisibilityChoice>& choice = automatic.primary_visibility_choice();
  ASSERT_TRUE(choice.has_value());
  ASSERT_TRUE(choice->raster_ms.has_value() && choice->compute_ms.has_value());
  EXPECT_GT(*choice->raster_ms, 0.0);
  EXPECT_GT(*choice->compute_ms, 0.0);
  EXPECT_EQ(choice->method, faster_primary_visibility(*choice->raster_ms, *choice->compute_ms));
  EXPECT_EQ(automatic.primary_visibility(), choice->method);
  EXPECT_EQ(automatic.compute_visibility() != nullptr, choice->method == PrimaryVisibility::compute);
  // Later frames render with the winner alone, as the explicit method does.
  automatic.render(state);
  RasterPipeline fixed(scene, 320, 192, visibility_settings(choice->method));
  fixed.render(state);
  const Rendered a = read(automatic), f = read(fixed);
  EXPECT_EQ(a.ids, f.ids);
  EXPECT_EQ(a.albedo.pixels, f.albedo.pixels);
  EXPECT_EQ(automatic.primary_visibility_choice()->raster_ms, choice->raster_ms);  // timed once only
}

TEST_F(PrimaryVisibilityChoiceTest, GlWorkTimeGrowsWithTheWork) {
  if (software_gl_renderer(current_gl_renderer())) GTEST_SKIP() << "needs a GPU: software renderers' queries mean nothing";
  const Scene scene = testing::mirror_floor_with_wall(-4.0f);
  const FrameState state = testing::camera_looking_down_the_floor();
  RasterPipeline raster(scene, 1024, 1024, visibility_settings(PrimaryVisibility::raster));
  raster.render(state);  // compiles and allocates before anything is timed
  const double nothing = time_gl_work_ms([] {});
  const double once = time_gl_work_ms([&] { raster.render(state); });
  const double eight = time_gl_work_ms([&] {
    for (int i = 0; i < 8; ++i) raster.render(state);
  });
  EXPECT_GE(nothing, 0.0);
  EXPECT_GT(once, nothing);
  EXPECT_GT(eight, 2.0 * once);
}

}  // namespace
}  // namespace glint::render
