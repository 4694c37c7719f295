// A scene file's camera path whose points are all one point is an error at its JSON path, like a
// path of one point (it was "walkthrough: camera.points: spline: needs at least 2 distinct control
// points", without the path); targets that are all one point stay a moving camera looking at it.
#include "scene/scene_json_parser.h"

#include "core/error.h"
#include "scene/camera_path.h"
#include "scene/load_scene.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

TEST(SceneJsonCameraPath, APathOfOnePointRepeatedIsAnErrorAtItsJsonPath) {
  const std::string message = testing::error_of([] {
    parse_scene_description(R"({"meshes": [{"file": "a.obj"}], "camera": {"path": [[0, 1, 0], [0, 1, 0], [0, 1, 0]]}})",
                            "scene.json");
  });
  EXPECT_NE(message.find("scene.json: /camera/path: the camera path's 3 points are all the same point"), std::string::npos)
      << message;
  EXPECT_NE(message.find("\"position\" and \"target\""), std::string::npos) << message;
}

TEST(SceneJsonCameraPath, TargetsOfOnePointKeepTheMovingCameraLookingAtIt) {
  testing::TempFolder folder;
  folder.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto scene_file = folder.write(
      "s.scene.json",
      R"({"meshes": [{"file": "tri.obj"}], "frames": 3, "light": {"position": [0, 2, 2]},
          "camera": {"path": [[-1, 0.5, 2], [1, 0.5, 2]], "targets": [[0, 0.5, 0], [0, 0.5, 0]]}})");
  const Scene scene = load_scene(scene_file.string());
  const WalkthroughAnimation animation(scene);
  for (int frame = 0; frame < 3; ++frame) EXPECT_EQ(animation.at(frame).camera.target, vec3(0, 0.5f, 0)) << frame;
  EXPECT_NE(animation.at(0).camera.position, animation.at(2).camera.position);
}

}  // namespace
}  // namespace glint
