// `glint render` on a user's own scene: a short preview unless --frames says otherwise, a fixed camera
// from the command line, --flat-normals, and one-line errors for malformed values.
#include "app/cli_runner.h"
#include "app/render_command.h"
#include "core/error.h"
#include "core/image.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

std::size_t line_count(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

std::size_t png_count(const fs::path& folder) {
  std::size_t count = 0;
  for (const auto& entry : fs::directory_iterator(folder)) count += entry.path().extension() == ".png" ? 1 : 0;
  return count;
}

TEST(RenderFlags, PreviewIsEightFramesFromTheFirstToTheLast) {
  EXPECT_EQ(preview_frames(4900), (std::vector<int>{0, 700, 1400, 2100, 2799, 3499, 4199, 4899}));
  EXPECT_EQ(preview_frames(5), (std::vector<int>{0, 1, 2, 3, 4})) << "a short walkthrough is rendered whole";
  EXPECT_EQ(preview_frames(8), (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7}));
  const std::vector<int> nine = preview_frames(9);
  ASSERT_EQ(nine.size(), 8u);
  EXPECT_EQ(nine.front(), 0);
  EXPECT_EQ(nine.back(), 8);
  EXPECT_TRUE(std::adjacent_find(nine.begin(), nine.end(), [](int a, int b) { return a >= b; }) == nine.end());
}

TEST(RenderFlags, PointFlagsAreThreeFiniteNumbers) {
  EXPECT_EQ(parse_point_flag("--camera", "1,2,3"), vec3(1, 2, 3));
  EXPECT_EQ(parse_point_flag("--camera", " -1.5 , 2e3,0 "), vec3(-1.5f, 2000.0f, 0.0f));
  for (const char* bad : {"", "1,2", "1,2,3,4", "a,b,c", "1,,3", "nan,0,0", "1e39,0,0", "1;2;3", "1 2 3"}) {
    try {
      (void)parse_point_flag("--target", bad);
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("--target \"" + std::string(bad) + "\": expected x,y,z"), std::string::npos)
          << error.what();
    }
  }
}

TEST(RenderFlags, MalformedValuesAreOneLineAndExitTwo) {
  TempFolder folder;
  const std::string out = " --out " + quoted(folder.path() / "run");
  struct Case {
    std::string arguments;
    std::string expected;
  };
  for (const Case& c : {Case{"--frames \"\"", "--frames"}, Case{"--frames \" \"", "empty value"},
                        Case{"--camera 1,2 --target 0,0,0", "--camera: \"1,2\": expected x,y,z"},
                        Case{"--camera 1,2,3 --target 0,zero,0", "--target: \"0,zero,0\": expected x,y,z"},
                        Case{"--camera 1,2,3", "--target"}, Case{"--target 1,2,3", "--camera"}}) {
    const CliResult r = run_glint("render atrium-simple " + c.arguments + out);
    EXPECT_EQ(r.exit_code, 2) << c.arguments << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.arguments << "\n" << r.err;
    EXPECT_FALSE(fs::exists(folder.path() / "run")) << c.arguments;
  }
  const CliResult same = run_glint("render atrium-simple --camera 1,2,3 --target 1,2,3" + out);
  EXPECT_EQ(same.exit_code, 1) << same.err;
  EXPECT_EQ(line_count(same.err), 1u) << same.err;
  EXPECT_NE(same.err.find("--camera 1,2,3 and --target 1,2,3 are the same point"), std::string::npos) << same.err;
}

TEST(RenderFlags, HelpStatesThePreviewAndTheNewFlags) {
  const CliResult r = run_glint("render --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* text : {"default: a preview of 8 frames", "or all", "--camera", "--target", "--flat-normals"})
    EXPECT_NE(r.out.find(text), std::string::npos) << text;
}

TEST(RenderFlags, InfoShowsAFixedCamera) {
  TempFolder folder;
  folder.write("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const fs::path scene = folder.write(
      "fixed.scene.json", R"({"meshes": [{"file": "tri.obj"}], "camera": {"position": [0.2, 0.3, 3], "target": [0.2, 0.3, 0]}})");
  const CliResult text = run_glint("info " + quoted(scene));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("camera    fixed at (0.20, 0.30, 3.00) looking at (0.20, 0.30, 0.00)"), std::string::npos)
      << text.out;
  const CliResult json = run_glint("info --json " + quoted(scene));
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(nlohmann::json::parse(json.out)["walkthrough"]["camera_fixed"], true);
}

// GlTest skips every test when this machine has no headless OpenGL 4.5 (the command would fail).
using RenderUserScene = GlTest;

// A 10 x 10 floor and a unit cube on it, as a user might export them.
fs::path write_plane_and_cube(const TempFolder& folder) {
  return folder.write("room.obj",
                      "v -5 0 -5\nv 5 0 -5\nv 5 0 5\nv -5 0 5\n"
                      "v -0.5 0 -0.5\nv 0.5 0 -0.5\nv 0.5 0 0.5\nv -0.5 0 0.5\n"
                      "v -0.5 1 -0.5\nv 0.5 1 -0.5\nv 0.5 1 0.5\nv -0.5 1 0.5\n"
                      "f 1 4 3 2\n"
                      "f 5 6 7 8\nf 9 12 11 10\nf 5 9 10 6\nf 6 10 11 7\nf 7 11 12 8\nf 8 12 9 5\n");
}

TEST_F(RenderUserScene, WithoutFramesRendersAPreviewAndSaysHowToRenderEverything) {
  TempFolder folder;
  const fs::path scene = write_plane_and_cube(folder);
  const fs::path out = folder.path() / "run";
  const CliResult r = run_glint("render " + quoted(scene) + " --width 32 --height 18 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("rendering a preview, 8 of the walkthrough's 4900 frames (0,700,1400,2100,2799,3499,4199,4899); "
                       "--frames all renders every frame"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(png_count(out), 8u);
  EXPECT_TRUE(fs::exists(out / "frame_04899.png"));
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["frames"]["count"], 8);
  EXPECT_EQ(run["frames"]["selection"], "0,700,1400,2100,2799,3499,4199,4899");

  // The default camera sees the floor and the cube: the image is not all sky.
  const ImageRgba8 image = read_png(out / "frame_00000.png");
  int differing = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) differing += image.at(x, y) != image.at(0, 0) ? 1 : 0;
  EXPECT_GT(differing, image.width * image.height / 4) << "most of the frame is one colour";
}

TEST_F(RenderUserScene, FramesAllFixedCameraAndFlatNormals) {
  TempFolder folder;
  write_plane_and_cube(folder);
  const fs::path scene = folder.write("short.scene.json", R"({"meshes": [{"file": "room.obj"}], "frames": 3})");
  const fs::path out = folder.path() / "run";
  const CliResult r = run_glint("render " + quoted(scene) +
                                " --frames all --camera 3,2,3 --target 0,0.5,0 --flat-normals --width 32 --height 18 "
                                "--out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("preview"), std::string::npos) << r.err;
  EXPECT_EQ(png_count(out), 3u);
  // The camera does not move: the three frames differ only where the light moved, not by a camera turn.
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["frames"]["count"], 3);
  EXPECT_NE(run["command"].get<std::string>().find("--camera 3,2,3"), std::string::npos);
}

}  // namespace
}  // namespace glint::testing
