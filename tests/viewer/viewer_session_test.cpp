// ViewerSession, the viewer's hold on the frame loop, on a headless context (no display needed): a
// flown view from exactly the walkthrough's camera is the walkthrough's frame (so free flight poses
// the scene at its frame and renders the same pipeline), going back to the path after flying gives
// the path's image again, a settings change rebuilds the loop, "light stays" keeps the light, and
// the rt reference of an rt view is that view.
#include "viewer/viewer_session.h"

#include "support/error_of.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

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
  const ImageRgba8 path = *session.render({frame, std::nullopt}).final_image;
  EXPECT_TRUE(session.last_render_rebuilt());
  // Another frame's pose first (on the path, then flown), so the flight must pose the scene at
  // `frame` itself.
  (void)session.render({frame - 300, std::nullopt});
  (void)session.render({frame - 300, session.walkthrough_state(frame - 300).camera});
  const FrameMeasurement flown = session.render({frame, session.walkthrough_state(frame).camera});
  EXPECT_EQ(flown.final_image->pixels, path.pixels);
  EXPECT_FALSE(flown.times.passes.empty()) << "the flown frame is timed too";
  ASSERT_TRUE(flown.ray_stats.has_value());
  EXPECT_GT(flown.ray_stats->rays_traced, 0u);
  const FrameMeasurement back = session.render({frame, std::nullopt});
  EXPECT_TRUE(session.last_render_rebuilt()) << "the pipeline rendered outside the loop";
  EXPECT_EQ(back.final_image->pixels, path.pixels);
  EXPECT_FALSE(session.debug_views().empty());
}

TEST_F(ViewerSessionTest, SettingsRebuildTheLoopAndBadOnesChangeNothing) {
  ViewerSession session(small_options(), pass_timing_for_renderer(context().renderer()));
  const ImageRgba8 hybrid = *session.render({2100, std::nullopt}).final_image;
  (void)session.render({2101, std::nullopt});
  EXPECT_FALSE(session.last_render_rebuilt()) << "a new frame alone runs the same loop";

  RenderOptions rt = session.options();
  rt.reflections = "rt";
  session.set_options(rt);
  const ImageRgba8 traced = *session.render({2100, std::nullopt}).final_image;
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
