// --reflections auto inside the whole frame (render/adaptive_reflections.h): where SSR never fails it
// is SSR; where SSR always fails it traces every reflective pixel in one list and marches no SSR; a
// ray budget is never exceeded; the tile classes debug view shows the decision.
#include "render/frame_pipeline.h"
#include "raster_test_scene.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint::render {
namespace {

using AdaptiveReflectionsTest = testing::GlTest;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// No blur, no fade, no tone curve: a pixel's final colour depends on its own reflection only. auto
// decides with fixed costs (a ray = 10 SSR pixels), free of timing noise.
FramePipelineSettings unfiltered(ReflectionMode mode) {
  FramePipelineSettings settings;
  settings.reflections = mode;
  settings.resolve.blur_radius = 0;
  settings.resolve.fade_end = 0.0f;
  settings.resolve.tone_map = ToneMap::none;
  settings.adaptive.fixed_costs = ReflectionCosts{1e-5, 1e-4};
  return settings;
}

// A strip of mirror floor before a wide lit wall that fills the view: SSR finds every reflection.
Scene mirror_strip_before_wall() {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 3.0f, 2.0f));
  const std::uint32_t floor = testing::add_material(scene, vec3(0.1f), 1.0f);
  const std::uint32_t wall = testing::add_material(scene, vec3(0.8f, 0.6f, 0.3f));
  testing::add_quad(scene, vec3(-0.5f, 0.0f, 4.0f), vec3(1.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -6.0f), floor);
  testing::add_quad(scene, vec3(-50.0f, -1.0f, -4.0f), vec3(100.0f, 0.0f, 0.0f), vec3(0.0f, 50.0f, 0.0f), wall);
  return scene;
}

// A mirror floor under an emissive ceiling behind the camera's image plane, the camera looking
// steeply down: every reflected ray leaves the screen, so SSR fails on every reflective pixel.
Scene mirror_floor_under_ceiling() {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 3.0f, 0.0f));
  const std::uint32_t floor = testing::add_material(scene, vec3(0.1f), 1.0f);
  const std::uint32_t ceiling = testing::add_material(scene, vec3(0.0f));
  scene.materials[ceiling].emissive = vec3(4.0f, 0.0f, 0.0f);
  testing::add_quad(scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), floor);
  testing::add_quad(scene, vec3(-6.0f, 4.0f, 8.0f), vec3(0.0f, 0.0f, -6.0f), vec3(12.0f, 0.0f, 0.0f), ceiling);
  return scene;
}

FrameState camera_looking_steeply_down() {
  const vec3 eye(0.0f, 1.5f, 6.0f);
  return testing::look_at(eye, eye + vec3(0.0f, -std::sin(glm::radians(60.0f)), -std::cos(glm::radians(60.0f))),
                          vec3(0.0f, 3.0f, 0.0f));
}

// auto needs a frame of history: the first frame knows nothing of SSR and runs SSR + rays everywhere.
struct AutoFrames {
  FramePipeline pipeline;
  AdaptiveFrameStats last;
  AutoFrames(const Scene& scene, const FramePipelineSettings& settings, const FrameState& frame, int frames)
      : pipeline(scene, kWidth, kHeight, settings) {
    for (int i = 0; i < frames; ++i) {
      pipeline.render(frame);
      last = *pipeline.take_readback(pipeline.frames_rendered() - 1, /*wait=*/true)->adaptive;
    }
  }
};

ImageRgba8 render_once(const Scene& scene, ReflectionMode mode, const FrameState& frame) {
  FramePipeline pipeline(scene, kWidth, kHeight, unfiltered(mode));
  pipeline.render(frame);
  return pipeline.read_final();
}

TEST_F(AdaptiveReflectionsTest, WithoutSsrFailuresAutoEqualsSsr) {
  const Scene scene = mirror_strip_before_wall();
  const FrameState frame = testing::look_at(vec3(0.0f, 1.0f, 6.0f), vec3(0.0f, 1.0f, -4.0f), vec3(0.0f, 3.0f, 2.0f));
  FramePipeline ssr(scene, kWidth, kHeight, unfiltered(ReflectionMode::ssr));
  ssr.render(frame);
  ASSERT_GT(ssr.read_counts()->reflective, 100u);
  ASSERT_EQ(ssr.read_counts()->failed, 0u) << "the scene is meant to have no SSR failure";

  AutoFrames automatic(scene, unfiltered(ReflectionMode::adaptive), frame, 3);
  EXPECT_EQ(automatic.pipeline.ray_trace_stats()->rays_traced, 0u);
  EXPECT_EQ(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::rt_only)], 0u);
  EXPECT_EQ(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::ssr_fallback)], 0u)
      << "SSR failed nowhere last frame: SSR alone, no ray list";
  EXPECT_GT(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::ssr_only)], 0u);
  EXPECT_EQ(automatic.last.reflective_pixels, ssr.read_counts()->reflective);
  EXPECT_EQ(automatic.pipeline.read_final().pixels, ssr.read_final().pixels);
}

TEST_F(AdaptiveReflectionsTest, WhereSsrAlwaysFailsAutoTracesEveryPixelWithoutMarching) {
  const Scene scene = mirror_floor_under_ceiling();
  const FrameState frame = camera_looking_steeply_down();
  FramePipeline hybrid(scene, kWidth, kHeight, unfiltered(ReflectionMode::hybrid));
  hybrid.render(frame);
  ASSERT_EQ(hybrid.read_counts()->failed, hybrid.read_counts()->reflective) << "SSR is meant to fail everywhere";

  AutoFrames automatic(scene, unfiltered(ReflectionMode::adaptive), frame, 2);
  const std::uint32_t reflective = hybrid.read_counts()->reflective;
  EXPECT_EQ(automatic.pipeline.read_counts()->reflective, 0u) << "SSR marched no pixel";
  EXPECT_EQ(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::ssr_only)], 0u);
  EXPECT_EQ(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::ssr_fallback)], 0u);
  EXPECT_EQ(automatic.pipeline.ray_trace_stats()->rays_traced, reflective) << "one ray per reflective pixel, one list";
  EXPECT_EQ(automatic.pipeline.read_final().pixels, render_once(scene, ReflectionMode::rt, frame).pixels);
}

TEST_F(AdaptiveReflectionsTest, TheRayBudgetIsNeverExceeded) {
  // SSR fails on every reflective pixel here, so every frame wants thousands of rays; the camera
  // moves, still and fast, so the motion-scaled budget changes too.
  const Scene scene = mirror_floor_under_ceiling();
  FramePipelineSettings settings = unfiltered(ReflectionMode::adaptive);
  constexpr std::uint32_t kBudget = 300;
  settings.adaptive.budget.rays = kBudget;
  FramePipeline pipeline(scene, kWidth, kHeight, settings);
  std::uint32_t most_wanted = 0;
  float lowest_factor = 1.0f;
  for (const float x : {0.0f, 0.0f, 0.01f, 0.5f, 1.0f, 1.0f, 1.0f}) {
    FrameState frame = camera_looking_steeply_down();
    frame.camera.position.x += x;
    frame.camera.target.x += x;
    pipeline.render(frame);
    const FrameReadback readback = *pipeline.take_readback(pipeline.frames_rendered() - 1, /*wait=*/true);
    ASSERT_TRUE(readback.ray_stats && readback.adaptive);
    EXPECT_LE(readback.ray_stats->rays_traced, kBudget) << "camera x " << x;
    ASSERT_TRUE(readback.adaptive->ray_budget);
    EXPECT_LE(*readback.adaptive->ray_budget, kBudget);
    most_wanted = std::max(most_wanted, readback.adaptive->rays_wanted);
    lowest_factor = std::min(lowest_factor, readback.adaptive->budget_factor);
  }
  EXPECT_GT(most_wanted, kBudget) << "the budget must bite for the test to mean anything";
  EXPECT_LT(lowest_factor, 1.0f) << "the fast frames lowered the budget";
}

TEST_F(AdaptiveReflectionsTest, TheTileClassesViewShowsTheDecision) {
  const Scene scene = mirror_floor_under_ceiling();
  AutoFrames automatic(scene, unfiltered(ReflectionMode::adaptive), camera_looking_steeply_down(), 2);
  bool found = false;
  for (const DebugView& view : automatic.pipeline.read_debug_views()) {
    if (view.name != "tile_classes") continue;
    found = true;
    int red = 0;
    for (const auto& p : view.image.pixels) red += p.x > 150 && p.y < 80;
    EXPECT_GT(red, kWidth * kHeight / 4) << "rays-only tiles are red";
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace glint::render
