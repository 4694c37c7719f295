// FrameLoop::submit with a camera (the viewer's free flight): the frame is posed, its structures
// updated and its light placed at the frame submitted, only the camera is the given one. A flown
// camera at frame F after frames elsewhere renders exactly what a fresh loop renders at F from that
// camera: the deformed meshes of F, not those of the frame the flight started at.
#include "app/frame_loop.h"
#include "scene/presets.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

using FrameLoopCamera = testing::GlTest;

constexpr int kStart = 2000;  // where the flight starts
constexpr int kFrame = 2100;  // where it is shown: a deforming creature near the camera

// atrium-simple with the light held still, so two frames differ by their deformation only.
Scene still_light_atrium() {
  Scene scene = make_preset("atrium-simple");
  scene.walkthrough.light.points = {scene.walkthrough.light.points.front()};
  scene.light.position = scene.walkthrough.light.points.front();
  return scene;
}

render::FramePipelineSettings hybrid_embree() {
  render::FramePipelineSettings settings;
  settings.reflections = render::ReflectionMode::hybrid;
  settings.ray_tracing.backend = "embree";  // the quickest to build on two cores
  return settings;
}

TEST_F(FrameLoopCamera, AFlownFrameIsTheSubmittedFramesPoseFromTheGivenCamera) {
  const FrameLoopOptions options{64, 36};
  const PassTimingMethod timing = pass_timing_for_renderer(context().renderer());
  const Scene atrium = still_light_atrium();  // made once: generating the preset takes longest here
  Scene flying_scene = atrium;
  FrameLoop flying(flying_scene, hybrid_embree(), options, timing);
  ASSERT_TRUE(flying.deforms());
  CameraState camera = flying.animation().at(kFrame).camera;
  camera.position += vec3(0.0f, 0.4f, 0.0f);  // off the path

  (void)flying.run(kStart, camera);
  const FrameMeasurement measured = flying.run(kFrame, camera);
  EXPECT_EQ(measured.frame, kFrame);
  ASSERT_TRUE(measured.accel_update_ms.has_value()) << "the flown frame updates the structures";
  ASSERT_TRUE(measured.ray_stats.has_value());
  EXPECT_GT(measured.ray_stats->rays_traced, 0u);
  const ImageRgba8 flown = flying.pipeline().read_final();

  Scene fresh_scene = atrium;
  FrameLoop fresh(fresh_scene, hybrid_embree(), options, timing);
  (void)fresh.run(kFrame, camera);
  EXPECT_EQ(fresh.pipeline().read_final().pixels, flown.pixels) << "frame F's pose, whatever came before";
  (void)fresh.run(kStart, camera);
  EXPECT_NE(fresh.pipeline().read_final().pixels, flown.pixels)
      << "the deformation of the start frame would look different from the same camera";
  (void)fresh.run(kFrame);
  EXPECT_NE(fresh.pipeline().read_final().pixels, flown.pixels) << "the given camera, not the path's";
}

}  // namespace
}  // namespace glint
