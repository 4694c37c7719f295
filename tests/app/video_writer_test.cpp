#include "app/video_writer.h"
#include "core/error.h"
#include "core/image.h"
#include "support/error_of.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

namespace glint {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::ScopedEnv;
using testing::TempFolder;

// Runs a shell command (test code only) and returns its stdout.
std::string run_and_capture(const std::string& command) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  if (!pipe) return {};
  std::string output;
  std::array<char, 256> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe.get()) != nullptr) output += buffer.data();
  return output;
}

// ffprobe's key=value description of the first video stream, with frames counted by decoding.
std::map<std::string, std::string> probe_video(const fs::path& video) {
  const std::string output = run_and_capture(
      "ffprobe -v error -count_frames -select_streams v:0 "
      "-show_entries stream=codec_name,width,height,pix_fmt,nb_read_frames -of default=noprint_wrappers=1 '" +
      video.string() + "'");
  std::map<std::string, std::string> values;
  std::istringstream lines(output);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t equals = line.find('=');
    if (equals != std::string::npos) values[line.substr(0, equals)] = line.substr(equals + 1);
  }
  return values;
}

// Frame `index` of `video` decoded back to RGBA through ffmpeg and a PNG.
ImageRgba8 decode_frame(const fs::path& video, int index, const fs::path& png) {
  run_and_capture("ffmpeg -v error -y -i '" + video.string() + "' -vf 'select=eq(n\\," + std::to_string(index) +
                  ")' -frames:v 1 '" + png.string() + "'");
  return read_png(png);
}

bool near(glm::u8vec4 a, glm::u8vec4 b, int tolerance) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(int(a[c]) - int(b[c])) > tolerance) return false;
  return true;
}

const std::array<glm::u8vec4, 6> kColours = {glm::u8vec4(200, 30, 30, 255),  glm::u8vec4(30, 200, 30, 255),
                                             glm::u8vec4(30, 30, 200, 255),  glm::u8vec4(220, 220, 40, 255),
                                             glm::u8vec4(128, 128, 128, 255), glm::u8vec4(20, 180, 200, 255)};

class FfmpegVideoWriterTest : public ::testing::Test {
protected:
  void SetUp() override {
    if (!find_program_on_path("ffmpeg") || !find_program_on_path("ffprobe"))
      GTEST_SKIP() << "ffmpeg and ffprobe are not on PATH";
  }
  TempFolder folder_;
};

TEST_F(FfmpegVideoWriterTest, SixSolidFramesEncodeToSixFramesOfTheRightSize) {
  const fs::path path = folder_.path() / "walk.mp4";
  {
    FfmpegVideoWriter video(path, 32, 18, 30.0);
    for (const glm::u8vec4 colour : kColours) video.add_frame(ImageRgba8(32, 18, colour));
    EXPECT_EQ(video.frame_count(), 6);
    EXPECT_FALSE(fs::exists(path));  // only the temporary exists until finish
    video.finish();
  }
  ASSERT_TRUE(fs::exists(path));
  const auto info = probe_video(path);
  EXPECT_EQ(info.at("codec_name"), "h264");
  EXPECT_EQ(info.at("pix_fmt"), "yuv420p");
  EXPECT_EQ(info.at("width"), "32");
  EXPECT_EQ(info.at("height"), "18");
  EXPECT_EQ(info.at("nb_read_frames"), "6");
  // Frames keep their order and (up to the lossy YUV round trip) their colour.
  for (const int index : {0, 3, 5}) {
    const ImageRgba8 decoded = decode_frame(path, index, folder_.path() / ("frame" + std::to_string(index) + ".png"));
    ASSERT_EQ(decoded.width, 32);
    EXPECT_TRUE(near(decoded.at(16, 9), kColours[static_cast<std::size_t>(index)], 8))
        << "frame " << index << ": " << int(decoded.at(16, 9).x) << "," << int(decoded.at(16, 9).y) << ","
        << int(decoded.at(16, 9).z);
  }
  // Nothing else (no temporary) is left in the folder besides the decoded PNGs.
  for (const auto& entry : fs::directory_iterator(folder_.path()))
    EXPECT_TRUE(entry.path() == path || entry.path().extension() == ".png") << entry.path();
}

TEST_F(FfmpegVideoWriterTest, OddSizesArePaddedToEven) {
  const fs::path path = folder_.path() / "odd.mkv";
  FfmpegVideoWriter video(path, 33, 17, 24.0);
  for (int i = 0; i < 3; ++i) video.add_frame(ImageRgba8(33, 17, kColours[static_cast<std::size_t>(i)]));
  video.finish();
  const auto info = probe_video(path);
  EXPECT_EQ(info.at("width"), "34");
  EXPECT_EQ(info.at("height"), "18");
  EXPECT_EQ(info.at("nb_read_frames"), "3");
  const ImageRgba8 first = decode_frame(path, 0, folder_.path() / "first.png");
  EXPECT_TRUE(near(first.at(10, 8), kColours[0], 8));  // the picture stays at the top left
}

TEST_F(FfmpegVideoWriterTest, DestroyedUnfinishedWriterLeavesNoFile) {
  const fs::path path = folder_.path() / "abandoned.mp4";
  {
    FfmpegVideoWriter video(path, 32, 18, 30.0);
    for (int i = 0; i < 3; ++i) video.add_frame(ImageRgba8(32, 18, kColours[static_cast<std::size_t>(i)]));
    // Wait until ffmpeg has created its (temporary) output, so that the destructor really has a file
    // to remove and a running encoder to stop. A wait, not a timing assertion: the bound only keeps a
    // broken ffmpeg from hanging the test.
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (fs::directory_iterator(folder_.path()) == fs::directory_iterator() &&
           std::chrono::steady_clock::now() < give_up)
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    ASSERT_FALSE(fs::directory_iterator(folder_.path()) == fs::directory_iterator());
    EXPECT_FALSE(fs::exists(path));
  }
  EXPECT_TRUE(fs::directory_iterator(folder_.path()) == fs::directory_iterator());
}

TEST_F(FfmpegVideoWriterTest, WrongFrameSizeIsAnError) {
  const fs::path path = folder_.path() / "sizes.mp4";
  FfmpegVideoWriter video(path, 32, 18, 30.0);
  video.add_frame(ImageRgba8(32, 18, kColours[0]));
  const std::string message = error_of([&] { video.add_frame(ImageRgba8(18, 32, kColours[1])); });
  EXPECT_NE(message.find("frame 1 is 18x32, the video is 32x18"), std::string::npos) << message;
  video.add_frame(ImageRgba8(32, 18, kColours[1]));  // the writer is still usable
  video.finish();
  EXPECT_EQ(probe_video(path).at("nb_read_frames"), "2");
}

TEST_F(FfmpegVideoWriterTest, FinishWithoutFramesIsAnErrorAndLeavesNoFile) {
  const fs::path path = folder_.path() / "empty.mp4";
  {
    FfmpegVideoWriter video(path, 32, 18, 30.0);
    EXPECT_NE(error_of([&] { video.finish(); }).find("no frames"), std::string::npos);
  }
  EXPECT_TRUE(fs::directory_iterator(folder_.path()) == fs::directory_iterator());
}

TEST(FfmpegVideoWriter, MissingFfmpegIsAClearError) {
  TempFolder empty_bin;
  const ScopedEnv path("PATH", empty_bin.path().string());
  const std::string message = error_of([&] { FfmpegVideoWriter video(empty_bin.path() / "v.mp4", 32, 18, 30.0); });
  EXPECT_EQ(message.rfind("--video needs ffmpeg on PATH", 0), 0u) << message;
}

// A stand-in "ffmpeg" that fails at once: the error must carry its exit status and its message, glint
// must survive the broken pipe (no SIGPIPE death), and no file may be left.
TEST(FfmpegVideoWriter, FailingFfmpegIsAnErrorWithItsOutput) {
  TempFolder temp;
  const fs::path fake = temp.write("bin/ffmpeg", "#!/bin/sh\necho 'first line' >&2\necho 'boom: encoder exploded' >&2\nexit 3\n");
  fs::permissions(fake, fs::perms::owner_all);
  const ScopedEnv path("PATH", (temp.path() / "bin").string());
  const fs::path video_path = temp.path() / "broken.mp4";
  std::string message;
  {
    FfmpegVideoWriter video(video_path, 256, 256, 30.0);
    // 256 KiB frames overflow the pipe, so a write meets the exited child (EPIPE) or finish() sees it.
    message = error_of([&] {
      for (int i = 0; i < 8; ++i) video.add_frame(ImageRgba8(256, 256, kColours[0]));
      video.finish();
    });
  }
  EXPECT_NE(message.find(video_path.string()), std::string::npos) << message;
  EXPECT_NE(message.find("exit status 3"), std::string::npos) << message;
  EXPECT_NE(message.find("first line | boom: encoder exploded"), std::string::npos) << message;
  EXPECT_FALSE(fs::exists(video_path));
  EXPECT_EQ(std::distance(fs::directory_iterator(temp.path()), fs::directory_iterator()), 1);  // bin/ only
}

TEST(FfmpegVideoWriter, BadArgumentsAreErrors) {
  TempFolder temp;
  EXPECT_NE(error_of([&] { FfmpegVideoWriter v(temp.path() / "v.avi", 32, 18, 30.0); }).find(".mp4, .mov or .mkv"),
            std::string::npos);
  EXPECT_NE(error_of([&] { FfmpegVideoWriter v(temp.path() / "v.mp4", 0, 18, 30.0); }).find("not positive"),
            std::string::npos);
  EXPECT_NE(error_of([&] { FfmpegVideoWriter v(temp.path() / "v.mp4", 32, 18, 0.0); }).find("not positive"),
            std::string::npos);
  EXPECT_NE(error_of([&] { FfmpegVideoWriter v(temp.path() / "no" / "v.mp4", 32, 18, 30.0); }).find("does not exist"),
            std::string::npos);
}

TEST(FindProgramOnPath, FindsExecutablesOnly) {
  TempFolder temp;
  const fs::path tool = temp.write("a/tool", "#!/bin/sh\n");
  fs::permissions(tool, fs::perms::owner_all);
  temp.write("b/data", "not executable");
  fs::permissions(temp.path() / "b" / "data", fs::perms::owner_read);
  const ScopedEnv path("PATH", (temp.path() / "b").string() + ":" + (temp.path() / "a").string());
  EXPECT_EQ(find_program_on_path("tool"), tool);
  EXPECT_FALSE(find_program_on_path("data").has_value());  // no execute bit (even root needs one)
  EXPECT_FALSE(find_program_on_path("missing").has_value());
}

}  // namespace
}  // namespace glint
