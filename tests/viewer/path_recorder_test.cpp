// `glint view` records the flown camera into a scene file's camera path: the saved file loads with
// the flight as its walkthrough (a fixed camera replaced, the field of view kept).
#include "viewer/path_recorder.h"

#include "scene/load_scene.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

namespace glint::viewer {
namespace {

using glint::testing::error_of;
using glint::testing::TempFolder;

CameraState camera_at(vec3 position) {
  CameraState camera;
  camera.position = position;
  camera.target = position + vec3(0.0f, 0.0f, -3.0f);
  return camera;
}

TEST(PathRecorder, SavedSceneFileFollowsTheFlight) {
  const TempFolder folder;
  folder.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const auto scene_file = folder.write(
      "room.scene.json",
      R"({"meshes": [{"file": "tri.obj"}],
          // a fixed camera, replaced by the recording
          "camera": {"fov_y_degrees": 45, "position": [0, 0, 4], "target": [0, 0, 0]}})");
  PathRecorder recorder;
  recorder.sample(camera_at(vec3(0.0f, 0.0f, 4.0f)));
  EXPECT_EQ(recorder.size(), 0u) << "nothing is kept before start()";
  recorder.start();
  recorder.sample(camera_at(vec3(0.0f, 0.0f, 4.0f)));
  recorder.sample(camera_at(vec3(0.1f, 0.0f, 4.0f)));  // closer than kMinStep: skipped
  recorder.sample(camera_at(vec3(1.0f, 0.0f, 4.0f)));
  recorder.sample(camera_at(vec3(2.0f, 0.5f, 4.0f)));
  recorder.stop();
  recorder.sample(camera_at(vec3(3.0f, 0.0f, 4.0f)));
  ASSERT_EQ(recorder.size(), 3u);

  const auto out = folder.path() / "room.recorded.scene.json";
  recorder.save(scene_file, out);
  const Scene scene = load_scene(out.string());
  const CameraPathSpec& path = scene.walkthrough.camera;
  ASSERT_EQ(path.points.size(), 3u);
  EXPECT_EQ(path.points[2], vec3(2.0f, 0.5f, 4.0f));
  ASSERT_EQ(path.targets.size(), 3u);
  EXPECT_EQ(path.targets[0], vec3(0.0f, 0.0f, 4.0f - PathRecorder::kTargetDistance));
  EXPECT_EQ(path.fov_y_degrees, 45.0f);
}

TEST(PathRecorder, TooShortARecordingOrAPresetIsRefused) {
  const TempFolder folder;
  PathRecorder recorder;
  recorder.start();
  recorder.sample(camera_at(vec3(0.0f)));
  EXPECT_NE(error_of([&] { recorder.save("room.scene.json", folder.path() / "out.scene.json"); })
                .find("record: 1 camera point recorded"),
            std::string::npos);
  recorder.sample(camera_at(vec3(5.0f)));
  EXPECT_NE(error_of([&] { recorder.save("atrium", folder.path() / "out.scene.json"); })
                .find("the scene atrium is not a scene file"),
            std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(folder.path() / "out.scene.json"));
}

}  // namespace
}  // namespace glint::viewer
