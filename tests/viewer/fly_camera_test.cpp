// The viewer's free camera starts where the walkthrough's camera is and looks where it looks, walks
// level in its own frame, and keeps its pitch short of straight up or down.
#include "viewer/fly_camera.h"

#include <gtest/gtest.h>

namespace glint::viewer {
namespace {

void expect_near(vec3 a, vec3 b, float tolerance = 1e-4f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(FlyCamera, StartsAtTheCameraLookingAtItsTarget) {
  CameraState walkthrough;
  walkthrough.position = vec3(1.0f, 2.0f, 3.0f);
  walkthrough.target = vec3(4.0f, 2.0f - 3.0f, 3.0f);  // 45 degrees down towards +x
  const FlyCamera fly(walkthrough);
  const CameraState state = fly.state(50.0f);
  expect_near(state.position, walkthrough.position);
  expect_near(glm::normalize(state.target - state.position), glm::normalize(walkthrough.target - walkthrough.position));
  EXPECT_EQ(state.fov_y_degrees, 50.0f);
}

TEST(FlyCamera, MovesLevelInItsOwnFrameAtItsSpeed) {
  CameraState walkthrough;
  walkthrough.position = vec3(0.0f);
  walkthrough.target = vec3(0.0f, -1.0f, -1.0f);  // looking down the -z axis, tilted down
  FlyCamera fly(walkthrough);
  const float speed = fly.speed();
  fly.move(vec3(0.0f, 0.0f, 1.0f), 2.0f);  // forward: along -z, not into the floor
  expect_near(fly.position(), vec3(0.0f, 0.0f, -2.0f * speed));
  fly.move(vec3(1.0f, 0.0f, 0.0f), 1.0f);  // right: +x
  expect_near(fly.position(), vec3(speed, 0.0f, -2.0f * speed));
  fly.move(vec3(0.0f, 1.0f, 0.0f), 1.0f);  // up
  expect_near(fly.position(), vec3(speed, speed, -2.0f * speed));
  fly.scroll(1.0f);
  EXPECT_NEAR(fly.speed(), speed * 1.2f, 1e-5f);
}

TEST(FlyCamera, PitchStopsShortOfStraightUp) {
  FlyCamera fly;
  fly.turn(0.0f, -1e6f);  // mouse far up
  const vec3 forward = fly.forward();
  EXPECT_GT(forward.y, 0.99f);
  EXPECT_LT(forward.y, 1.0f);
  EXPECT_TRUE(std::isfinite(glm::length(fly.state(60.0f).view()[0])));
}

}  // namespace
}  // namespace glint::viewer
