// `glint render --hold-frame N` as a user runs it: two frames held at one walkthrough frame of a
// scene whose camera, light and cube move are the same PNG byte for byte (mirror reflections, the
// paper's blur), run.json records the hold, --help says what is held, and bad values are one line
// (exit 2 for a value that is no frame number, 1 for a frame the walkthrough does not have).
#include "app/cli_runner.h"
#include "glossy_room_scene.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using RenderHoldFrameCli = GlTest;  // skips without headless OpenGL 4.5

std::string file_bytes(const fs::path& path) { return read_text_file(path); }

TEST_F(RenderHoldFrameCli, HeldFramesAreTheSameImageAndTheRunRecordsTheHold) {
  TempFolder folder;
  const fs::path scene = write_glossy_room(folder);
  const std::string common = " --reflections hybrid --glossy off --denoise off --frames 10:11 --width 32 --height 18";
  const fs::path held = folder.path() / "held";
  CliResult r = run_glint("render " + quoted(scene) + common + " --hold-frame 5 --out " + quoted(held));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(file_bytes(held / "frame_00010.png"), file_bytes(held / "frame_00011.png"));
  const nlohmann::json run = nlohmann::json::parse(read_text_file(held / "run.json"));
  EXPECT_EQ(run["options"]["hold_frame"], 5) << run["options"].dump();

  const fs::path moving = folder.path() / "moving";
  r = run_glint("render " + quoted(scene) + common + " --out " + quoted(moving));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(file_bytes(moving / "frame_00010.png"), file_bytes(moving / "frame_00011.png"));
  EXPECT_TRUE(nlohmann::json::parse(read_text_file(moving / "run.json"))["options"]["hold_frame"].is_null());
}

TEST(RenderHoldFrameFlags, HelpAndBadValues) {
  const CliResult help = run_glint("render --help");
  EXPECT_NE(help.out.find("--hold-frame"), std::string::npos);
  EXPECT_NE(help.out.find("camera, light and deformed meshes"), std::string::npos) << help.out;

  TempFolder folder;
  const std::string out = " --out " + quoted(folder.path() / "run");
  for (const char* value : {"-1", "two", "1.5", ""}) {
    SCOPED_TRACE(value);
    const CliResult r = run_glint(std::string("render atrium-simple --hold-frame \"") + value + "\"" + out);
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_LE(line_count(r.err), 2) << r.err;  // the reason, and CLI11's pointer to --help
    EXPECT_NE(r.err.find("--hold-frame"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("a walkthrough frame number"), std::string::npos) << r.err;
  }
  EXPECT_FALSE(fs::exists(folder.path() / "run"));
}

TEST_F(RenderHoldFrameCli, AFrameTheWalkthroughLacksIsOneLine) {
  TempFolder folder;
  const fs::path scene = write_glossy_room(folder);
  const CliResult r = run_glint("render " + quoted(scene) + " --hold-frame 1900 --frames 0 --width 32 --height 18 --out " +
                                quoted(folder.path() / "run"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--hold-frame 1900: the walkthrough has 1900 frames (0 to 1899)"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace glint::testing
