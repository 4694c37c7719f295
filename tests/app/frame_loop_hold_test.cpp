// FrameLoop's hold frame (glint render --hold-frame): every frame is posed at the held walkthrough
// frame (camera, light, deformed meshes) while the frame number goes on. Mirror reflections without
// the denoiser are then the same image frame after frame, byte for byte, where the walkthrough
// itself moves the camera, the light and a deforming wall; the number still reaches the glossy
// sampler, whose samples change from frame to frame; a frame outside the walkthrough is refused.
#include "app/frame_loop.h"
#include "core/error.h"
#include "../render/raster_test_scene.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

class FrameLoopHold : public testing::GlTest {
protected:
  static PassTimingMethod timing() { return pass_timing_for_renderer(context().renderer()); }
};

constexpr int kHeld = 3;

// The raster tests' mirror floor and red wall, with a walkthrough that moves the camera and the
// light every frame and a wall that deforms.
Scene moving_scene() {
  Scene scene = testing::mirror_floor_with_wall(-4.0f);
  scene.walkthrough.camera.points = {vec3(-1.0f, 1.5f, 6.0f), vec3(1.0f, 1.5f, 6.0f)};
  scene.walkthrough.camera.targets = {vec3(0.0f, 0.8f, -4.0f), vec3(0.0f, 0.8f, -4.0f)};
  scene.walkthrough.light.points = {vec3(-3.0f, 6.0f, 0.0f), vec3(3.0f, 6.0f, 0.0f)};
  scene.walkthrough.light.period_frames = 8;
  Mesh& wall = scene.meshes[1];
  wall.deformable = true;
  wall.deform = SineDeform{1, 0, 0.3f, 1.0f, 6.0f};
  return scene;
}

render::FramePipelineSettings hybrid(bool glossy) {
  render::FramePipelineSettings settings;
  settings.reflections = render::ReflectionMode::hybrid;
  settings.sampling.glossy = glossy;  // the test scene's materials have roughness 0.25
  return settings;
}

struct TwoFrames {
  ImageRgba8 first, second;
  std::vector<vec3> first_wall, second_wall;
  int second_number = -1;
};

// Frames kHeld and kHeld + 1 of a fresh loop.
TwoFrames two_frames(bool glossy, std::optional<int> hold, PassTimingMethod timing) {
  Scene scene = moving_scene();
  FrameLoopOptions options{64, 36};
  options.hold_frame = hold;
  FrameLoop loop(scene, hybrid(glossy), options, timing);
  EXPECT_TRUE(loop.deforms());
  TwoFrames frames;
  (void)loop.run(kHeld);
  frames.first = loop.pipeline().read_final();
  frames.first_wall = scene.meshes[1].positions;
  frames.second_number = loop.run(kHeld + 1).frame;
  frames.second = loop.pipeline().read_final();
  frames.second_wall = scene.meshes[1].positions;
  return frames;
}

TEST_F(FrameLoopHold, MirrorFramesAreByteIdenticalWhileTheNumberAdvances) {
  const TwoFrames held = two_frames(false, kHeld, timing());
  EXPECT_EQ(held.second_number, kHeld + 1) << "the frame keeps its own number";
  EXPECT_EQ(held.first.pixels, held.second.pixels);
  EXPECT_EQ(held.first_wall, held.second_wall) << "the wall stays posed at the held frame";

  const TwoFrames moving = two_frames(false, std::nullopt, timing());
  EXPECT_EQ(moving.first.pixels, held.first.pixels) << "the held frame is that frame of the walkthrough";
  EXPECT_NE(moving.first.pixels, moving.second.pixels) << "without the hold, camera, light and wall move";
  EXPECT_NE(moving.first_wall, moving.second_wall);
}

TEST_F(FrameLoopHold, TheFrameNumberStillDrivesTheGlossySamples) {
  const TwoFrames held = two_frames(true, kHeld, timing());
  EXPECT_EQ(held.first_wall, held.second_wall);
  EXPECT_NE(held.first.pixels, held.second.pixels) << "frame numbers 3 and 4 draw other GGX samples";
}

TEST_F(FrameLoopHold, AFrameOutsideTheWalkthroughIsRefused) {
  Scene scene = moving_scene();
  FrameLoopOptions options{32, 18};
  options.hold_frame = scene.walkthrough.frame_count;
  try {
    FrameLoop loop(scene, hybrid(false), options, pass_timing_for_renderer(context().renderer()));
    FAIL() << "no error";
  } catch (const Error& error) {
    EXPECT_STREQ(error.what(), "--hold-frame 10: the walkthrough has 10 frames (0 to 9)");
  }
}

}  // namespace
}  // namespace glint
