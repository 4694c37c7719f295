// --reflections auto inside the whole frame (render/adaptive_reflections.h): where SSR never fails it
// is SSR; where SSR always fails it traces every reflective pixel in one list and marches no SSR;
// where rays are cheaper it is rt with no SSR, depth pyramid or classification pass; where SSR is
// cheaper and fails on part of the frame it keeps per-tile decisions; a whole-frame path is re-checked;
// a ray budget is never exceeded; the tile classes debug view shows the decision.
#include "render/frame_pipeline.h"
#include "raster_test_scene.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint::render {
namespace {

using AdaptiveReflectionsTest = testing::GlTest;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// No blur, no fade, no tone curve: a pixel's final colour depends on its own reflection only. auto
// decides with fixed costs (a ray = 10 SSR pixels; each stage's fixed part and the classification
// 0.01 ms), free of timing noise.
FramePipelineSettings unfiltered(ReflectionMode mode) {
  FramePipelineSettings settings;
  settings.reflections = mode;
  settings.resolve.blur_radius = 0;
  settings.resolve.fade_end = 0.0f;
  settings.resolve.tone_map = ToneMap::none;
  settings.adaptive.fixed_costs = ReflectionStageCosts{{1e-5, 1e-4}, 0.01, 0.01, 0.01};
  return settings;
}

// A strip of mirror floor with a lit wall behind its left half only: SSR finds the wall's reflection
// on the left and fails on the right, where the mirrored rays leave the screen over nothing.
Scene mirror_floor_half_walled() {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 3.0f, 2.0f));
  const std::uint32_t floor = testing::add_material(scene, vec3(0.1f), 1.0f);
  const std::uint32_t wall = testing::add_material(scene, vec3(0.8f, 0.6f, 0.3f));
  testing::add_quad(scene, vec3(-3.0f, 0.0f, 4.0f), vec3(6.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -6.0f), floor);
  testing::add_quad(scene, vec3(-50.0f, -1.0f, -4.0f), vec3(50.0f, 0.0f, 0.0f), vec3(0.0f, 50.0f, 0.0f), wall);
  return scene;
}

FrameState camera_over_the_strip() {
  return testing::look_at(vec3(0.0f, 1.0f, 6.0f), vec3(0.0f, 1.0f, -4.0f), vec3(0.0f, 3.0f, 2.0f));
}

// One frame of auto, as the frame loop sees it: its readback and the passes the timer saw.
struct AutoFrame {
  FrameReadback readback;
  std::vector<std::string> passes;
  bool ran(const std::string& pass) const { return std::find(passes.begin(), passes.end(), pass) != passes.end(); }
};

// auto needs a frame of history: the first frame knows nothing of SSR and runs SSR + rays everywhere.
struct AutoFrames {
  FramePipeline pipeline;
  GpuTimer timer{PassTimingMethod::finish_wall_clock};
  AdaptiveFrameStats last;
  AutoFrames(const Scene& scene, const FramePipelineSettings& settings, const FrameState& frame, int frames)
      : pipeline(scene, kWidth, kHeight, settings) {
    for (int i = 0; i < frames; ++i) render(frame);
  }
  AutoFrame render(const FrameState& frame) {
    timer.begin_frame();
    pipeline.render(frame, &timer);
    timer.end_frame();
    AutoFrame result{*pipeline.take_readback(pipeline.frames_rendered() - 1, /*wait=*/true), {}};
    const std::optional<FrameTimes> times = timer.take_frame(pipeline.frames_rendered() - 1, /*wait=*/true);
    for (const PassTime& pass : times->passes) result.passes.push_back(pass.name);
    last = *result.readback.adaptive;
    return result;
  }
};

ImageRgba8 render_once(const Scene& scene, ReflectionMode mode, const FrameState& frame) {
  FramePipeline pipeline(scene, kWidth, kHeight, unfiltered(mode));
  pipeline.render(frame);
  return pipeline.read_final();
}

TEST_F(AdaptiveReflectionsTest, WithoutSsrFailuresAutoEqualsSsr) {
  const Scene scene = testing::mirror_strip_before_wall();
  const FrameState frame = camera_over_the_strip();
  FramePipeline ssr(scene, kWidth, kHeight, unfiltered(ReflectionMode::ssr));
  ssr.render(frame);
  ASSERT_GT(ssr.read_counts()->reflective, 100u);
  ASSERT_EQ(ssr.read_counts()->failed, 0u) << "the scene is meant to have no SSR failure";

  AutoFrames automatic(scene, unfiltered(ReflectionMode::adaptive), frame, 2);
  // Frame 1 decided per tile (frame 0's SSR told it nothing fails): SSR alone, no ray list.
  EXPECT_EQ(automatic.last.path, ReflectionPath::per_tile);
  EXPECT_EQ(automatic.pipeline.ray_trace_stats()->rays_traced, 0u);
  EXPECT_EQ(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::rt_only)], 0u);
  EXPECT_EQ(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::ssr_fallback)], 0u)
      << "SSR failed nowhere last frame: SSR alone, no ray list";
  EXPECT_GT(automatic.last.class_tiles[static_cast<std::size_t>(TileClass::ssr_only)], 0u);
  EXPECT_EQ(automatic.last.reflective_pixels, ssr.read_counts()->reflective);
  EXPECT_EQ(automatic.pipeline.read_final().pixels, ssr.read_final().pixels);

  // From then on every tile is SSR only, so the frame is ssr's: SSR over the whole image, no
  // classification, no ray list, trace or hit shading.
  const AutoFrame whole = automatic.render(frame);
  EXPECT_EQ(whole.readback.adaptive->path, ReflectionPath::all_ssr);
  EXPECT_TRUE(whole.ran("ssr"));
  EXPECT_FALSE(whole.ran("classify"));
  EXPECT_FALSE(whole.ran("ray_list") || whole.ran("hit_shade"));
  EXPECT_FALSE(whole.readback.ray_stats) << "nothing traced";
  EXPECT_EQ(whole.readback.adaptive->reflective_pixels, ssr.read_counts()->reflective);
  EXPECT_EQ(automatic.pipeline.read_final().pixels, ssr.read_final().pixels);
}

TEST_F(AdaptiveReflectionsTest, AWholeFrameOfSsrEndsWhereSsrStartsFailing) {
  const Scene scene = testing::mirror_strip_before_wall();
  AutoFrames automatic(scene, unfiltered(ReflectionMode::adaptive), camera_over_the_strip(), 3);
  ASSERT_EQ(automatic.last.path, ReflectionPath::all_ssr);
  // The camera looks 45 degrees down onto the strip: the mirrored rays leave the screen above it.
  const FrameState down = testing::look_at(vec3(0.0f, 2.0f, 5.0f), vec3(0.0f, 0.0f, 3.0f), vec3(0.0f, 3.0f, 2.0f));
  const AutoFrame failing = automatic.render(down);
  ASSERT_EQ(failing.readback.adaptive->path, ReflectionPath::all_ssr) << "decided before its SSR ran";
  ASSERT_GT(failing.readback.ssr_counts->failed, 0u);
  const AutoFrame next = automatic.render(down);
  EXPECT_EQ(next.readback.adaptive->path, ReflectionPath::per_tile) << "SSR alone no longer suffices";
  EXPECT_TRUE(next.ran("classify"));
  EXPECT_GT(next.readback.ray_stats->rays_traced, 0u);
}

TEST_F(AdaptiveReflectionsTest, WhereRaysAreCheaperAutoIsRtWithoutSsrPyramidOrClassification) {
  // An SSR pixel costs 10 rays (the H200's atrium: a ray is cheaper than a marched pixel), on a
  // frame where SSR succeeds on half the floor.
  const Scene scene = mirror_floor_half_walled();
  const FrameState frame = camera_over_the_strip();
  FramePipelineSettings settings = unfiltered(ReflectionMode::adaptive);
  settings.adaptive.fixed_costs = ReflectionStageCosts{{1e-4, 1e-5}, 0.01, 0.01, 0.01};
  AutoFrames automatic(scene, settings, frame, 2);
  const ImageRgba8 rt = render_once(scene, ReflectionMode::rt, frame);
  for (int i = 0; i < 3; ++i) {
    const AutoFrame whole = automatic.render(frame);
    EXPECT_EQ(whole.readback.adaptive->path, ReflectionPath::all_rays) << "frame " << i;
    EXPECT_FALSE(whole.ran("classify")) << "no classification pass";
    EXPECT_FALSE(whole.ran("ssr")) << "no depth pyramid, no SSR march";
    EXPECT_FALSE(whole.readback.ssr_counts) << "SSR counted nothing: it did not run";
    EXPECT_TRUE(whole.ran("ray_list"));
    ASSERT_TRUE(whole.readback.ray_stats);
    EXPECT_GT(whole.readback.ray_stats->rays_traced, 100u);
    EXPECT_EQ(whole.readback.ray_stats->rays_traced, whole.readback.adaptive->reflective_pixels)
        << "one ray per reflective pixel";
    EXPECT_EQ(automatic.pipeline.read_final().pixels, rt.pixels) << "rt's image exactly";
  }
}

TEST_F(AdaptiveReflectionsTest, WhereSsrIsCheaperAndFailsOnPartOfTheFrameAutoDecidesPerTile) {
  const Scene scene = mirror_floor_half_walled();
  const FrameState frame = camera_over_the_strip();
  AutoFrames automatic(scene, unfiltered(ReflectionMode::adaptive), frame, 2);
  for (int i = 0; i < 3; ++i) {
    const AutoFrame tiled = automatic.render(frame);
    const AdaptiveFrameStats& stats = *tiled.readback.adaptive;
    EXPECT_EQ(stats.path, ReflectionPath::per_tile) << "frame " << i;
    EXPECT_TRUE(tiled.ran("classify") && tiled.ran("ssr") && tiled.ran("ray_list"));
    EXPECT_GT(stats.class_tiles[static_cast<std::size_t>(TileClass::ssr_only)], 0u) << "the walled half: SSR alone";
    EXPECT_GT(stats.class_tiles[static_cast<std::size_t>(TileClass::rt_only)] +
                  stats.class_tiles[static_cast<std::size_t>(TileClass::ssr_fallback)],
              0u)
        << "the open half: rays";
    EXPECT_LT(tiled.readback.ray_stats->rays_traced, stats.reflective_pixels);
  }
}

TEST_F(AdaptiveReflectionsTest, AWholeFramePathIsRecheckedPerTile) {
  // SSR fails everywhere: all rays, but every recheck_frames frames a per-tile frame (which forgets
  // the stale history: SSR + rays on every tile) measures SSR again.
  const Scene scene = testing::mirror_floor_under_ceiling();
  FramePipelineSettings settings = unfiltered(ReflectionMode::adaptive);
  settings.adaptive.recheck_frames = 3;
  AutoFrames automatic(scene, settings, testing::camera_looking_steeply_down(), 2);
  std::string paths;
  for (int i = 0; i < 8; ++i) {
    const AutoFrame frame = automatic.render(testing::camera_looking_steeply_down());
    paths += frame.readback.adaptive->path == ReflectionPath::all_rays ? "R" : "T";
    EXPECT_EQ(frame.ran("classify"), frame.readback.adaptive->path == ReflectionPath::per_tile) << "frame " << i;
  }
  // Frames 2-4 all rays, 5 per tile (no history: SSR + rays), 6 per tile (decides from 5's tiles),
  // 7-9 all rays again.
  EXPECT_EQ(paths, "RRRTTRRR");
}

TEST_F(AdaptiveReflectionsTest, WhereSsrAlwaysFailsAutoTracesEveryPixelWithoutMarching) {
  const Scene scene = testing::mirror_floor_under_ceiling();
  const FrameState frame = testing::camera_looking_steeply_down();
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
  const Scene scene = testing::mirror_floor_under_ceiling();
  FramePipelineSettings settings = unfiltered(ReflectionMode::adaptive);
  constexpr std::uint32_t kBudget = 300;
  settings.adaptive.budget.rays = kBudget;
  FramePipeline pipeline(scene, kWidth, kHeight, settings);
  std::uint32_t most_wanted = 0;
  float lowest_factor = 1.0f;
  for (const float x : {0.0f, 0.0f, 0.01f, 0.5f, 1.0f, 1.0f, 1.0f}) {
    FrameState frame = testing::camera_looking_steeply_down();
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
  const Scene scene = testing::mirror_floor_under_ceiling();
  AutoFrames automatic(scene, unfiltered(ReflectionMode::adaptive), testing::camera_looking_steeply_down(), 2);
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
