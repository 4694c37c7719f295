// ViewerSession, the viewer's hold on the frame loop, on a headless context (no display needed): a
// flown view from exactly the walkthrough's camera is the walkthrough's frame (so free flight poses
// the scene at its frame and renders the same pipeline), flying on to other frames runs the same loop
// (no rebuild) and shows each frame's deformation, going back to the path after flying gives the
// path's image again, the final image stays on the GPU until asked for (the picture is a GPU copy of
// it), a settings change rebuilds the loop, "light stays" keeps the light, and the rt reference of
// an rt view is that view.
#include "viewer/viewer_session.h"

#include "viewer/picture_texture.h"

#include "support/error_of.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <memory>

namespace glint::viewer {
namespace {

using ViewerSessionTest = testing::GlTest;
using glint::testing::error_of;

RenderOptions small_options() {
  RenderOptions options;
  options.scene = "atrium-simple";
  options.width = 64;
  options.height = 36;
  options.backend = "embree";
  return options;
}

TEST_F(ViewerSessionTest, FlyingFromThePathCameraSeesThePathFrame) {
  ViewerSession session(small_options(), pass_timing_for_renderer(context().renderer()));
  const int frame = 2100;  // a deforming creature near the camera, SSR failures traced
  (void)session.render({frame, std::nullopt});
  const ImageRgba8 path = session.final_image();
  EXPECT_TRUE(session.last_render_rebuilt());
  // Another frame's pose first (on the path, then flown), so the flight must pose the scene at
  // `frame` itself.
  (void)session.render({frame - 300, std::nullopt});
  (void)session.render({frame - 300, session.walkthrough_state(frame - 300).camera});
  const FrameMeasurement flown = session.render({frame, session.walkthrough_state(frame).camera});
  EXPECT_FALSE(session.last_render_rebuilt()) << "a flown frame runs the same loop";
  EXPECT_EQ(session.final_image().pixels, path.pixels);
  EXPECT_FALSE(flown.times.passes.empty()) << "the flown frame is timed too";
  ASSERT_TRUE(flown.ray_stats.has_value());
  EXPECT_GT(flown.ray_stats->rays_traced, 0u);
  (void)session.render({frame, std::nullopt});
  EXPECT_FALSE(session.last_render_rebuilt()) << "back on the path, the same loop";
  EXPECT_EQ(session.final_image().pixels, path.pixels);
  EXPECT_FALSE(session.debug_views().empty());
}

// Flying while the walkthrough plays: each flown frame is posed at its own frame (the deformed
// meshes of frame F, not those of the frame where the flight started), through the same loop.
TEST_F(ViewerSessionTest, AFlightShowsTheDeformationOfEachFrame) {
  const int start = 2000, frame = 2100;
  CameraState camera;
  {
    ViewerSession probe(small_options(), pass_timing_for_renderer(context().renderer()));
    camera = probe.walkthrough_state(frame).camera;
  }
  camera.position += vec3(0.0f, 0.4f, 0.0f);  // off the path
  const auto still_light_session = [&] {
    auto session = std::make_unique<ViewerSession>(small_options(), pass_timing_for_renderer(context().renderer()));
    session->set_fixed_light(session->walkthrough_state(start).light_position);  // frames differ by deformation only
    return session;
  };
  const std::unique_ptr<ViewerSession> flight = still_light_session();
  (void)flight->render({start, camera});
  const ImageRgba8 at_start = flight->final_image();
  (void)flight->render({frame, camera});
  EXPECT_FALSE(flight->last_render_rebuilt()) << "the flight goes on in the same loop";
  const ImageRgba8 flown = flight->final_image();
  EXPECT_NE(flown.pixels, at_start.pixels) << "the creature deformed between the two frames";

  const std::unique_ptr<ViewerSession> fresh = still_light_session();
  (void)fresh->render({frame, camera});
  EXPECT_EQ(fresh->final_image().pixels, flown.pixels);
}

// The viewer shows the final image from the GPU: a frame is not read back, and the picture copied
// on the GPU from the pipeline's texture is the final image (rows bottom first, as GL keeps them).
TEST_F(ViewerSessionTest, TheFinalImageStaysOnTheGpuAndThePictureIsItsCopy) {
  ViewerSession session(small_options(), pass_timing_for_renderer(context().renderer()));
  const FrameMeasurement measured = session.render({2100, std::nullopt});
  EXPECT_FALSE(measured.final_image.has_value()) << "no host round trip per frame";
  ASSERT_NE(session.final_texture(), 0u);
  PictureTexture picture;
  picture.copy_from(session.final_texture(), session.rendered_width(), session.rendered_height());
  EXPECT_TRUE(picture.bottom_row_first());
  const ImageRgba8 expected = session.final_image();
  ASSERT_EQ(picture.width(), expected.width);
  ASSERT_EQ(picture.height(), expected.height);
  ImageRgba8 copied(expected.width, expected.height);
  glPixelStorei(GL_PACK_ALIGNMENT, 4);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glGetTextureImage(picture.id(), 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(copied.pixels.size() * 4),
                    copied.pixels.data());
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x)
      ASSERT_EQ(copied.at(x, expected.height - 1 - y), expected.at(x, y)) << "pixel " << x << "," << y;
  picture.upload(expected);
  EXPECT_FALSE(picture.bottom_row_first());
}

TEST_F(ViewerSessionTest, SettingsRebuildTheLoopAndBadOnesChangeNothing) {
  ViewerSession session(small_options(), pass_timing_for_renderer(context().renderer()));
  (void)session.render({2100, std::nullopt});
  const ImageRgba8 hybrid = session.final_image();
  (void)session.render({2101, std::nullopt});
  EXPECT_FALSE(session.last_render_rebuilt()) << "a new frame alone runs the same loop";

  RenderOptions rt = session.options();
  rt.reflections = "rt";
  session.set_options(rt);
  (void)session.render({2100, std::nullopt});
  const ImageRgba8 traced = session.final_image();
  EXPECT_TRUE(session.last_render_rebuilt());
  EXPECT_NE(traced.pixels, hybrid.pixels);
  EXPECT_EQ(session.render_reference({2100, std::nullopt}).pixels, traced.pixels);

  RenderOptions bad = session.options();
  bad.accel = "lbvh";  // not with embree
  EXPECT_NE(error_of([&] { session.set_options(bad); }).find("--accel lbvh"), std::string::npos);
  EXPECT_EQ(session.options().accel, "sah");
}

TEST_F(ViewerSessionTest, AStayingLightStaysWhereItWas) {
  ViewerSession session(small_options(), pass_timing_for_renderer(context().renderer()));
  const vec3 at_100 = session.walkthrough_state(100).light_position;
  ASSERT_NE(session.walkthrough_state(400).light_position, at_100) << "the light moves along its path";
  session.set_fixed_light(at_100);
  EXPECT_EQ(session.walkthrough_state(400).light_position, at_100);
  session.set_fixed_light(std::nullopt);
  EXPECT_NE(session.walkthrough_state(400).light_position, at_100);
  EXPECT_NE(error_of([&] { session.render({session.frame_count(), std::nullopt}); }).find("outside the walkthrough"),
            std::string::npos);
}

}  // namespace
}  // namespace glint::viewer
