#include "scene/camera_path.h"
#include "scene/light_path.h"

#include "core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace glint {
namespace {

Walkthrough s_path_walkthrough() {
  Walkthrough w;
  w.camera.points = {{0, 1.5f, 0}, {1, 1.5f, 0.5f}, {4, 1.6f, 3}, {4.5f, 1.7f, 6},
                     {3, 1.7f, 7.5f}, {1, 1.6f, 9}, {0.5f, 1.5f, 12}, {2, 1.5f, 15}};
  w.light.points = {{0, 5, 0}, {10, 5, 0}};
  w.light.period_frames = 980;
  w.frame_count = 4900;
  w.frames_per_second = 30.0f;
  return w;
}

// Expects `body` to throw a glint::Error whose message contains `needle`.
template <typename Body>
void expect_error_mentioning(const Body& body, const std::string& needle) {
  try {
    body();
    ADD_FAILURE() << "no error thrown; expected one mentioning '" << needle << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
  }
}

TEST(WalkthroughAnimation, StartsAtTheFirstCameraPointAndEndsAtTheLast) {
  const Walkthrough w = s_path_walkthrough();
  const WalkthroughAnimation animation(w, vec3(0.0f));
  EXPECT_EQ(animation.frame_count(), 4900);
  EXPECT_EQ(animation.at(0).camera.position, w.camera.points.front());
  EXPECT_EQ(animation.at(4899).camera.position, w.camera.points.back());
  EXPECT_EQ(animation.at(0).frame, 0);
  EXPECT_EQ(animation.at(4899).frame, 4899);
  EXPECT_FLOAT_EQ(animation.camera_path_length(), CatmullRomSpline(w.camera.points).length());
}

TEST(WalkthroughAnimation, MovesTheCameraAtConstantSpeed) {
  const WalkthroughAnimation animation(s_path_walkthrough(), vec3(0.0f));
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0, sum = 0.0;
  for (int f = 1; f < animation.frame_count(); ++f) {
    const double step = glm::distance(animation.at(f - 1).camera.position, animation.at(f).camera.position);
    lo = std::min(lo, step);
    hi = std::max(hi, step);
    sum += step;
  }
  const double mean = sum / (animation.frame_count() - 1);
  EXPECT_LT((hi - lo) / mean, 0.01);
  EXPECT_NEAR(animation.camera_speed_per_frame(), mean, 1e-3 * mean);
  EXPECT_NEAR(animation.camera_speed_per_frame(), animation.camera_path_length() / 4899.0f, 1e-6f);
}

TEST(WalkthroughAnimation, LooksAlongThePathWithoutTargets) {
  const Walkthrough w = s_path_walkthrough();
  const WalkthroughAnimation animation(w, vec3(0.0f));
  const CatmullRomSpline path(w.camera.points);
  for (int f : {0, 700, 2450, 4000, 4899}) {
    const CameraState camera = animation.at(f).camera;
    const float s = path.length() * static_cast<float>(f) / 4899.0f;
    EXPECT_GT(glm::dot(glm::normalize(camera.target - camera.position), path.tangent_at_distance(s)), 0.9999f) << f;
    EXPECT_NEAR(glm::length(camera.up), 1.0f, 1e-6f);
  }
}

TEST(WalkthroughAnimation, FollowsTheTargetSplineAtTheSameFraction) {
  Walkthrough w = s_path_walkthrough();
  w.camera.targets = {{5, 1, 5}, {6, 1, 9}, {2, 0.5f, 18}};
  const WalkthroughAnimation animation(w, vec3(0.0f));
  const CatmullRomSpline targets(w.camera.targets);
  EXPECT_EQ(animation.at(0).camera.target, w.camera.targets.front());
  EXPECT_EQ(animation.at(4899).camera.target, w.camera.targets.back());
  for (int f : {1000, 2450, 3333}) {
    const float fraction = static_cast<float>(f) / 4899.0f;
    EXPECT_LT(glm::distance(animation.at(f).camera.target, targets.position_at_fraction(fraction)), 1e-4f) << f;
  }
}

TEST(WalkthroughAnimation, OneTargetIsAFixedLookAtPoint) {
  Walkthrough w = s_path_walkthrough();
  w.camera.targets = {{2, 1, 7}};
  const WalkthroughAnimation animation(w, vec3(0.0f));
  for (int f : {0, 1234, 4899}) EXPECT_EQ(animation.at(f).camera.target, vec3(2, 1, 7));
}

TEST(WalkthroughAnimation, TimeIsFrameOverFramesPerSecondAndFovIsPassedOn) {
  Walkthrough w = s_path_walkthrough();
  w.frames_per_second = 24.0f;
  w.camera.fov_y_degrees = 45.0f;
  const WalkthroughAnimation animation(w, vec3(0.0f));
  EXPECT_FLOAT_EQ(animation.at(0).time_seconds, 0.0f);
  EXPECT_FLOAT_EQ(animation.at(36).time_seconds, 1.5f);
  EXPECT_FLOAT_EQ(animation.at(4899).time_seconds, 4899.0f / 24.0f);
  EXPECT_EQ(animation.at(100).camera.fov_y_degrees, 45.0f);
}

TEST(WalkthroughAnimation, ViewIsFiniteWhenLookingStraightDownOrAtItself) {
  Walkthrough w = s_path_walkthrough();
  w.camera.points = {{0, 10, 0}, {0, 0, 0}};  // the tangent is -y, parallel to the world's up
  const WalkthroughAnimation animation(w, vec3(0.0f));
  const CameraState camera = animation.at(100).camera;
  EXPECT_LT(std::abs(glm::dot(glm::normalize(camera.target - camera.position), camera.up)), 0.999f);
  const mat4 view = camera.view();
  for (int c = 0; c < 4; ++c) EXPECT_TRUE(is_finite(vec3(view[c])) && std::isfinite(view[c].w)) << c;
  // The camera looks down its -z axis: the target ends up straight ahead.
  const vec4 ahead = view * vec4(camera.target, 1.0f);
  EXPECT_NEAR(ahead.x, 0.0f, 1e-5f);
  EXPECT_NEAR(ahead.y, 0.0f, 1e-5f);
  EXPECT_LT(ahead.z, 0.0f);

  // A target on the camera: at() looks along the path instead; view() of such a state stays finite.
  w.camera.points = {{0, 0, 0}, {4, 0, 0}};
  w.camera.targets = {{2, 0, 0}};
  w.frame_count = 5;
  const WalkthroughAnimation through(w, vec3(0.0f));
  const CameraState on_target = through.at(2).camera;  // the middle of the path: at the target
  ASSERT_LT(glm::distance(on_target.position, vec3(2, 0, 0)), 1e-6f);
  EXPECT_GT(glm::distance(on_target.target, on_target.position), 0.5f);
  EXPECT_GT(glm::dot(glm::normalize(on_target.target - on_target.position), vec3(1, 0, 0)), 0.999f);
  CameraState degenerate;
  degenerate.position = degenerate.target = vec3(1, 2, 3);
  const mat4 degenerate_view = degenerate.view();
  for (int c = 0; c < 4; ++c) EXPECT_TRUE(is_finite(vec3(degenerate_view[c])));
}

TEST(WalkthroughAnimation, MovesTheLightAlongItsPathAndKeepsTheRestLightWithoutOne) {
  Walkthrough w = s_path_walkthrough();
  const WalkthroughAnimation moving(w, vec3(7, 7, 7));
  EXPECT_EQ(moving.at(0).light_position, vec3(0, 5, 0));
  EXPECT_EQ(moving.at(490).light_position, vec3(10, 5, 0));
  EXPECT_FLOAT_EQ(moving.light_path_length(), 10.0f);
  w.light.points.clear();
  const WalkthroughAnimation resting(w, vec3(7, 7, 7));
  EXPECT_EQ(resting.at(0).light_position, vec3(7, 7, 7));
  EXPECT_EQ(resting.at(3000).light_position, vec3(7, 7, 7));
  EXPECT_EQ(resting.light_path_length(), 0.0f);

  Scene scene;
  scene.walkthrough = w;
  scene.light.position = vec3(-1, 4, 2);
  EXPECT_EQ(WalkthroughAnimation(scene).at(10).light_position, vec3(-1, 4, 2));
}

TEST(WalkthroughAnimation, OneFrameWalkthroughStaysAtTheStart) {
  Walkthrough w = s_path_walkthrough();
  w.frame_count = 1;
  const WalkthroughAnimation animation(w, vec3(0.0f));
  EXPECT_EQ(animation.at(0).camera.position, w.camera.points.front());
  EXPECT_EQ(animation.camera_speed_per_frame(), 0.0f);
}

TEST(WalkthroughAnimation, RejectsBadWalkthroughsWithClearMessages) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto with = [](auto edit) {
    Walkthrough w = s_path_walkthrough();
    edit(w);
    return w;
  };
  const vec3 rest(0.0f);
  expect_error_mentioning([&] { WalkthroughAnimation(with([](Walkthrough& w) { w.frame_count = 0; }), rest); },
                          "frame_count");
  expect_error_mentioning([&] { WalkthroughAnimation(with([](Walkthrough& w) { w.frames_per_second = 0; }), rest); },
                          "frames_per_second");
  expect_error_mentioning(
      [&] { WalkthroughAnimation(with([&](Walkthrough& w) { w.frames_per_second = nan; }), rest); },
      "frames_per_second");
  expect_error_mentioning([&] { WalkthroughAnimation(with([](Walkthrough& w) { w.light.period_frames = 0; }), rest); },
                          "period_frames");
  expect_error_mentioning(
      [&] { WalkthroughAnimation(with([](Walkthrough& w) { w.camera.points.resize(1); }), rest); }, "camera.points");
  expect_error_mentioning(
      [&] { WalkthroughAnimation(with([&](Walkthrough& w) { w.camera.points[3].y = nan; }), rest); }, "camera.points");
  expect_error_mentioning(
      [&] { WalkthroughAnimation(with([&](Walkthrough& w) { w.camera.targets = {{0, 0, 0}, {nan, 0, 0}}; }), rest); },
      "camera.targets");
  expect_error_mentioning(
      [&] { WalkthroughAnimation(with([&](Walkthrough& w) { w.light.points = {{0, 0, 0}, {nan, 0, 0}}; }), rest); },
      "light");
  expect_error_mentioning([&] { WalkthroughAnimation(with([](Walkthrough& w) { w.camera.fov_y_degrees = 0; }), rest); },
                          "fov");

  const WalkthroughAnimation animation(s_path_walkthrough(), rest);
  expect_error_mentioning([&] { (void)animation.at(-1); }, "frame -1");
  expect_error_mentioning([&] { (void)animation.at(4900); }, "frame 4900");
}

TEST(LightPath, PingPongsAlongThePolylineOncePerPeriod) {
  // An L of total length 8: (0,0,0) -> (4,0,0) -> (4,0,4).
  const LightPath light({{0, 0, 0}, {4, 0, 0}, {4, 0, 4}}, 100, vec3(9.0f));
  EXPECT_FLOAT_EQ(light.length(), 8.0f);
  EXPECT_EQ(light.at(0), vec3(0, 0, 0));
  EXPECT_EQ(light.at(25), vec3(4, 0, 0));   // a quarter period: half way along
  EXPECT_EQ(light.at(50), vec3(4, 0, 4));   // half a period: the last point
  EXPECT_EQ(light.at(75), vec3(4, 0, 0));   // and back
  EXPECT_EQ(light.at(100), vec3(0, 0, 0));  // one period: home again
  EXPECT_EQ(light.at(350), vec3(4, 0, 4));  // periodic
  EXPECT_LT(glm::distance(light.at(10), vec3(1.6f, 0, 0)), 1e-6f);   // 0.2 of the way out = 1.6
  EXPECT_LT(glm::distance(light.at(40), vec3(4, 0, 2.4f)), 1e-6f);   // 0.8 of the way out = 6.4
  EXPECT_LT(glm::distance(light.at(90), vec3(1.6f, 0, 0)), 1e-6f);   // mirror of frame 10
}

TEST(LightPath, MovesAtConstantSpeedOnAStraightLine) {
  const LightPath light({{0, 2, 0}, {0, 2, 10}}, 40, vec3(0.0f));
  for (int f = 1; f <= 20; ++f) EXPECT_NEAR(glm::distance(light.at(f - 1), light.at(f)), 0.5f, 1e-5f) << f;
  for (int f = 21; f <= 40; ++f) EXPECT_NEAR(light.at(f).z, light.at(f - 1).z - 0.5f, 1e-5f) << f;
}

TEST(LightPath, OnePointIsFixedAndNoPointsIsTheRestPosition) {
  const LightPath fixed({{1, 2, 3}}, 10, vec3(9.0f));
  const LightPath resting({}, 10, vec3(9.0f));
  for (int f : {0, 3, 5, 11, 1000}) {
    EXPECT_EQ(fixed.at(f), vec3(1, 2, 3));
    EXPECT_EQ(resting.at(f), vec3(9.0f));
  }
  EXPECT_EQ(fixed.length(), 0.0f);
}

TEST(LightPath, RejectsANonPositivePeriod) {
  EXPECT_THROW(LightPath({{0, 0, 0}, {1, 0, 0}}, 0, vec3(0.0f)), Error);
  EXPECT_THROW(LightPath({{0, 0, 0}, {1, 0, 0}}, -5, vec3(0.0f)), Error);
}

}  // namespace
}  // namespace glint
