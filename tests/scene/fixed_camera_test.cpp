// A camera that does not move: one point and one target in a walkthrough, "camera": {"position",
// "target"} in a scene file, and a glTF file's own camera.
#include "scene/camera_path.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_test_builder.h"
#include "scene/scene_json_loader.h"
#include "scene/scene_json_parser.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include "core/error.h"
#include "core/log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace glint {
namespace {

using nlohmann::json;
using testing::error_of;
using testing::GltfBuilder;
using testing::TempFolder;

void expect_near(const vec3& actual, const vec3& expected, float tolerance = 1e-4f) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

Walkthrough fixed_walkthrough() {
  Walkthrough w;
  w.camera = CameraPathSpec::fixed(vec3(1, 2, 3), vec3(1, 2, -7), 50.0f);
  w.light.points = {vec3(0, 5, 0), vec3(4, 5, 0)};
  w.frame_count = 100;
  return w;
}

TEST(FixedCamera, OnePointAndOneTargetStayPutForEveryFrame) {
  const WalkthroughAnimation animation(fixed_walkthrough(), vec3(0.0f));
  for (const int frame : {0, 37, 99}) {
    const FrameState state = animation.at(frame);
    EXPECT_EQ(state.camera.position, vec3(1, 2, 3));
    EXPECT_EQ(state.camera.target, vec3(1, 2, -7));
    EXPECT_FLOAT_EQ(state.camera.fov_y_degrees, 50.0f);
  }
  EXPECT_NE(animation.at(0).light_position, animation.at(49).light_position) << "the light still moves";
  EXPECT_EQ(animation.camera_path_length(), 0.0f);
  EXPECT_EQ(animation.camera_speed_per_frame(), 0.0f);
}

TEST(FixedCamera, OnePointNeedsExactlyOneTargetApartFromIt) {
  Walkthrough w = fixed_walkthrough();
  w.camera.targets.clear();
  EXPECT_NE(error_of([&] { WalkthroughAnimation(w, vec3(0.0f)); }).find("a fixed camera, which needs exactly 1 target"),
            std::string::npos);
  w.camera.targets = {vec3(1, 2, 3)};
  EXPECT_NE(error_of([&] { WalkthroughAnimation(w, vec3(0.0f)); }).find("target is its position"), std::string::npos);
  w.camera.points.clear();
  EXPECT_NE(error_of([&] { WalkthroughAnimation(w, vec3(0.0f)); }).find("camera.points is empty"), std::string::npos);
}

TEST(FixedCamera, SceneFileCameraPositionAndTarget) {
  const SceneDescription description = parse_scene_description(
      R"({"meshes": [{"file": "a.obj"}], "camera": {"position": [0, 1.5, 4], "target": [0, 1, 0], "fov_y_degrees": 35}})",
      "scene.json");
  ASSERT_TRUE(description.camera.has_value());
  EXPECT_EQ(description.camera->points, std::vector<vec3>{vec3(0, 1.5f, 4)});
  EXPECT_EQ(description.camera->targets, std::vector<vec3>{vec3(0, 1, 0)});
  EXPECT_FLOAT_EQ(description.camera->fov_y_degrees, 35.0f);

  const auto parse_error = [](const char* text) { return error_of([&] { parse_scene_description(text, "scene.json"); }); };
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "camera": {"position": [0, 1, 4]}})")
                .find("scene.json: /camera: a fixed camera needs \"target\" as well as \"position\""),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "camera": {"target": [0, 1, 4]}})")
                .find("scene.json: /camera: a fixed camera needs \"position\""),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}],
                "camera": {"position": [0, 1, 4], "target": [0, 0, 0], "path": [[0, 0, 1], [0, 0, 2]]}})")
                .find("scene.json: /camera/path: give either \"path\""),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "camera": {"position": [0, 1, 4], "target": [0, 1, 4]}})")
                .find("scene.json: /camera/target: the target equals the position"),
            std::string::npos);
  EXPECT_NE(parse_error(R"({"meshes": [{"file": "a.obj"}], "camera": {"position": [0, 1], "target": [0, 1, 4]}})")
                .find("scene.json: /camera/position"),
            std::string::npos);
}

TEST(FixedCamera, SceneFileWithAFixedCameraRendersFromThere) {
  TempFolder folder;
  GltfBuilder gltf;
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}});
  folder.write("tri.gltf", gltf.gltf_text());
  const Scene scene = load_scene_json_text(
      R"({"meshes": [{"file": "tri.gltf"}], "camera": {"position": [0.3, 0.3, 2], "target": [0.3, 0.3, 0]}})",
      folder.path() / "a.scene.json");
  const WalkthroughAnimation animation(scene);
  EXPECT_EQ(animation.at(0).camera.position, vec3(0.3f, 0.3f, 2.0f));
  EXPECT_EQ(animation.at(animation.frame_count() - 1).camera.position, vec3(0.3f, 0.3f, 2.0f));
}

// A triangle and a camera node: translated to (0, 1, 5), turned 90 degrees about +Y (so it looks
// along -X), under a parent moved by (10, 0, 0).
GltfBuilder gltf_with_camera(const json& camera) {
  GltfBuilder gltf;
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}});
  gltf.json["cameras"] = json::array({camera});
  const float s = std::sqrt(0.5f);
  gltf.json["nodes"].push_back({{"camera", 0}, {"translation", {0, 1, 5}}, {"rotation", {0, s, 0, s}}});
  gltf.json["nodes"].push_back({{"translation", {10, 0, 0}}, {"children", {1}}});
  gltf.json["scenes"] = json::array({{{"nodes", {0, 2}}}});
  gltf.json["scene"] = 0;
  return gltf;
}

TEST(FixedCamera, GltfCameraNodeBecomesTheFixedCamera) {
  TempFolder folder;
  const GltfBuilder gltf =
      gltf_with_camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"aspectRatio", 1.5}}}});
  const Scene scene = load_gltf(folder.write("camera.gltf", gltf.gltf_text()));
  ASSERT_TRUE(scene.walkthrough.camera.is_fixed());
  const FrameState state = WalkthroughAnimation(scene).at(0);
  expect_near(state.camera.position, vec3(10, 1, 5));
  expect_near(glm::normalize(state.camera.target - state.camera.position), vec3(-1, 0, 0));
  EXPECT_NEAR(state.camera.fov_y_degrees, 0.5f * 180.0f / 3.14159265f, 1e-3f);
}

TEST(FixedCamera, GltfOrthographicCameraKeepsPlaceAndDirectionWithAWarning) {
  TempFolder folder;
  const GltfBuilder gltf =
      gltf_with_camera({{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}});
  ScopedLogCapture log;
  const Scene scene = load_gltf(folder.write("ortho.gltf", gltf.gltf_text()));
  EXPECT_EQ(log.count_warnings("camera 0 is orthographic"), 1);
  ASSERT_TRUE(scene.walkthrough.camera.is_fixed());
  expect_near(scene.walkthrough.camera.points.front(), vec3(10, 1, 5));
  EXPECT_FLOAT_EQ(scene.walkthrough.camera.fov_y_degrees, 60.0f);
}

TEST(FixedCamera, GltfWithoutCameraGetsTheDefaultLoop) {
  TempFolder folder;
  GltfBuilder gltf;
  gltf.add_mesh_node({{"attributes", {{"POSITION", gltf.add_vec3(testing::unit_triangle())}}}});
  const Scene scene = load_gltf(folder.write("plain.gltf", gltf.gltf_text()));
  EXPECT_FALSE(scene.walkthrough.camera.is_fixed());
  EXPECT_GT(WalkthroughAnimation(scene).camera_path_length(), 0.0f);
}

}  // namespace
}  // namespace glint
