#include "app/output_folder.h"
#include "core/error.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace glint {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::TempFolder;

TEST(OutputFolder, CreatesTheFolderAndItsParents) {
  TempFolder temp;
  const fs::path path = temp.path() / "runs" / "atrium" / "hybrid";
  const OutputFolder folder(path);
  EXPECT_TRUE(fs::is_directory(path));
  EXPECT_EQ(folder.path(), path);
}

TEST(OutputFolder, AcceptsAnExistingFolderAndKeepsItsFiles) {
  TempFolder temp;
  const fs::path kept = temp.write("out/notes.txt", "keep me");
  const OutputFolder folder(temp.path() / "out");
  EXPECT_TRUE(fs::exists(kept));
}

TEST(OutputFolder, ExistingFileIsRefused) {
  TempFolder temp;
  const fs::path file = temp.write("out", "a file, not a folder");
  EXPECT_EQ(error_of([&] { OutputFolder folder(file); }),
            "output folder '" + file.string() + "' exists and is not a folder");
  EXPECT_TRUE(fs::is_regular_file(file));
}

TEST(OutputFolder, ParentThatIsAFileIsAnErrorNamingThePath) {
  TempFolder temp;
  const fs::path file = temp.write("blocker", "x");
  const fs::path path = file / "out";
  const std::string message = error_of([&] { OutputFolder folder(path); });
  EXPECT_EQ(message.rfind("cannot create output folder '" + path.string() + "'", 0), 0u) << message;
}

TEST(OutputFolder, AFolderItCreatedIsRemovedWhenNothingWasWritten) {
  TempFolder temp;
  const fs::path unused = temp.path() / "unused";
  { const OutputFolder folder(unused); }
  EXPECT_FALSE(fs::exists(unused)) << "a run that failed before writing leaves no empty folder";
  const fs::path used = temp.path() / "used";
  {
    const OutputFolder folder(used);
    temp.write("used/run.json", "{}");
  }
  EXPECT_TRUE(fs::exists(used / "run.json"));
  fs::create_directories(temp.path() / "existing");
  { const OutputFolder folder(temp.path() / "existing"); }
  EXPECT_TRUE(fs::is_directory(temp.path() / "existing")) << "a folder it did not create stays";
}

TEST(OutputFolder, EarlierRunIsRefusedReplacedOrKept) {
  TempFolder temp;
  temp.write("out/frame_00001.png", "old");
  temp.write("out/frame_00001_albedo.png", "old");
  temp.write("out/timings.csv", "old");
  temp.write("out/.timings.csv.tmp-1-0", "old");
  temp.write("out/mine.txt", "keep");
  const std::string refused = error_of([&] { OutputFolder folder(temp.path() / "out", EarlierRun::refuse); });
  EXPECT_NE(refused.find("holds an earlier run"), std::string::npos) << refused;
  EXPECT_NE(refused.find("--overwrite"), std::string::npos) << refused;
  EXPECT_TRUE(fs::exists(temp.path() / "out/frame_00001.png"));
  { const OutputFolder kept(temp.path() / "out", EarlierRun::keep); }
  EXPECT_TRUE(fs::exists(temp.path() / "out/frame_00001.png"));
  { const OutputFolder replaced(temp.path() / "out", EarlierRun::replace); }
  std::vector<std::string> left;
  for (const auto& entry : fs::directory_iterator(temp.path() / "out")) left.push_back(entry.path().filename().string());
  EXPECT_EQ(left, std::vector<std::string>{"mine.txt"});
}

TEST(OutputFolder, RunOutputNames) {
  for (const char* name : {"run.json", "timings.csv", "walkthrough.mp4", "frame_00042.png", "frame_00042_normals.png",
                           ".run.json.tmp-123-4"})
    EXPECT_TRUE(is_run_output_name(name)) << name;
  for (const char* name : {"notes.txt", "frame.txt", "summary.json", ".hidden", "cells"})
    EXPECT_FALSE(is_run_output_name(name)) << name;
}

TEST(OutputFolder, FramePathsHaveFiveDigitsOrMore) {
  TempFolder temp;
  const OutputFolder folder(temp.path());
  EXPECT_EQ(folder.frame_path(0), temp.path() / "frame_00000.png");
  EXPECT_EQ(folder.frame_path(42), temp.path() / "frame_00042.png");
  EXPECT_EQ(folder.frame_path(4899), temp.path() / "frame_04899.png");
  EXPECT_EQ(folder.frame_path(99999), temp.path() / "frame_99999.png");
  EXPECT_EQ(folder.frame_path(123456), temp.path() / "frame_123456.png");
  EXPECT_NE(error_of([&] { folder.frame_path(-1); }).find("frame -1"), std::string::npos);
}

TEST(OutputFolder, DebugViewPathsNameFrameAndView) {
  TempFolder temp;
  const OutputFolder folder(temp.path());
  EXPECT_EQ(folder.debug_view_path(42, "ssr_mask"), temp.path() / "frame_00042_ssr_mask.png");
  EXPECT_EQ(folder.debug_view_path(7, "rt-hits"), temp.path() / "frame_00007_rt-hits.png");
  for (const char* bad : {"", "../x", "a/b", "with space", "dot.png"})
    EXPECT_NE(error_of([&] { folder.debug_view_path(1, bad); }).find("debug view name"), std::string::npos) << bad;
}

TEST(OutputFolder, OtherFilesArePlainNamesInTheFolder) {
  TempFolder temp;
  const OutputFolder folder(temp.path());
  EXPECT_EQ(folder.file("timings.csv"), temp.path() / "timings.csv");
  for (const char* bad : {"", ".", "..", "sub/timings.csv"})
    EXPECT_NE(error_of([&] { folder.file(bad); }).find("not a plain file name"), std::string::npos) << bad;
}

}  // namespace
}  // namespace glint
