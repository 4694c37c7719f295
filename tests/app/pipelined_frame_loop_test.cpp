// The pipelined frame loop (app/frame_loop.h): frames come back complete, in order and exactly once,
// a few frames late at most, and render exactly what the serialized loop renders: the same final
// images (PNG files byte for byte) and the same counters, with either pass-timing method. On
// llvmpipe the wall-clock method finishes every frame before submit() returns; GL queries leave
// frames in flight, which is what exercises the rings of queries and readback slots.
#include "app/frame_loop.h"
#include "app/image_writer_thread.h"
#include "core/error.h"
#include "core/image.h"
#include "scene/presets.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace glint {
namespace {

using PipelinedFrameLoop = testing::GlTest;
using testing::TempFolder;
namespace fs = std::filesystem;

constexpr int kWidth = 64;
constexpr int kHeight = 36;
// Deforming frames of atrium-simple with reflections on the floor and SSR failures to trace.
const std::vector<int> kFrames = {2100, 2101, 2102, 2103, 2104, 2105, 2106};

render::FramePipelineSettings settings_for(render::ReflectionMode mode) {
  render::FramePipelineSettings settings;
  settings.reflections = mode;
  settings.ray_tracing.backend = "cpu";
  settings.ray_tracing.update = rt::UpdatePolicy::refit;
  return settings;
}

std::vector<FrameMeasurement> run_loop(render::ReflectionMode mode, PassTimingMethod timing, bool serialized,
                                       std::size_t* most_in_flight = nullptr) {
  Scene scene = make_preset("atrium-simple");
  FrameLoopOptions options{kWidth, kHeight};
  options.capture_final = true;
  options.serialized = serialized;
  // Pipelined: every frame stays in flight until two later frames were submitted, so its results
  // are read from their slots after those frames rendered, as on a busy GPU.
  if (!serialized) options.keep_in_flight = kFramesInFlight - 1;
  FrameLoop loop(scene, settings_for(mode), options, timing);
  std::vector<FrameMeasurement> done;
  for (const int frame : kFrames) {
    std::vector<FrameMeasurement> finished = loop.submit(frame);
    if (serialized) {
      EXPECT_EQ(finished.size(), 1u) << "the serialized loop returns the frame it was given";
    } else {
      EXPECT_LE(finished.size(), 1u);
    }
    if (most_in_flight != nullptr) *most_in_flight = std::max(*most_in_flight, loop.frames_in_flight());
    EXPECT_LE(loop.frames_in_flight(), kFramesInFlight);
    for (FrameMeasurement& measured : finished) done.push_back(std::move(measured));
  }
  for (FrameMeasurement& measured : loop.drain()) done.push_back(std::move(measured));
  EXPECT_EQ(loop.frames_in_flight(), 0u);
  return done;
}

std::string file_bytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_complete_and_in_order(const std::vector<FrameMeasurement>& done, render::ReflectionMode mode) {
  ASSERT_EQ(done.size(), kFrames.size()) << "every frame exactly once";
  for (std::size_t i = 0; i < done.size(); ++i) {
    SCOPED_TRACE("frame " + std::to_string(kFrames[i]));
    EXPECT_EQ(done[i].frame, kFrames[i]) << "frame order";
    EXPECT_EQ(done[i].times.frame, i) << "the timer's frame of the same submission";
    ASSERT_TRUE(done[i].final_image.has_value());
    EXPECT_EQ(done[i].final_image->width, kWidth);
    ASSERT_TRUE(done[i].ssr_counts.has_value());
    EXPECT_GT(done[i].ssr_counts->reflective, 0u);
    std::vector<std::string> passes;
    for (const PassTime& pass : done[i].times.passes) passes.push_back(pass.name);
    if (mode == render::ReflectionMode::hybrid) {
      ASSERT_TRUE(done[i].ray_stats.has_value());
      EXPECT_EQ(done[i].ray_stats->rays_traced, done[i].ssr_counts->failed) << "hybrid traces the failed pixels";
      EXPECT_NE(std::find(passes.begin(), passes.end(), "hit_shade"), passes.end());
    } else {
      EXPECT_FALSE(done[i].ray_stats.has_value());
    }
    EXPECT_NE(std::find(passes.begin(), passes.end(), "resolve"), passes.end());
    EXPECT_TRUE(std::isfinite(done[i].frame_ms));
    EXPECT_TRUE(std::isfinite(done[i].latency_ms));
    EXPECT_TRUE(done[i].resident_bytes.has_value());
  }
}

TEST_F(PipelinedFrameLoop, WritesTheSerializedLoopsImagesAndCounts) {
  for (const render::ReflectionMode mode : {render::ReflectionMode::ssr, render::ReflectionMode::hybrid}) {
    for (const PassTimingMethod timing : {PassTimingMethod::gpu_queries, PassTimingMethod::finish_wall_clock}) {
      SCOPED_TRACE(std::string(render::reflection_mode_name(mode)) + ", " + std::string(pass_timing_name(timing)));
      const std::vector<FrameMeasurement> serialized = run_loop(mode, timing, /*serialized=*/true);
      std::size_t most_in_flight = 0;
      const std::vector<FrameMeasurement> pipelined = run_loop(mode, timing, /*serialized=*/false, &most_in_flight);
      EXPECT_GE(most_in_flight, kFramesInFlight - 1) << "every frame was read two frames late at least";
      expect_complete_and_in_order(serialized, mode);
      expect_complete_and_in_order(pipelined, mode);
      if (HasFailure()) return;

      // The same PNG files: the serialized images written in line, the pipelined ones by the worker.
      TempFolder folder;
      ImageWriterThread writer(2);
      for (std::size_t i = 0; i < kFrames.size(); ++i) {
        const std::string name = "frame_" + std::to_string(kFrames[i]) + ".png";
        write_png(folder.path() / ("serialized_" + name), *serialized[i].final_image);
        writer.write(folder.path() / ("pipelined_" + name), *pipelined[i].final_image);
      }
      writer.finish();
      for (std::size_t i = 0; i < kFrames.size(); ++i) {
        const std::string name = "frame_" + std::to_string(kFrames[i]) + ".png";
        const std::string expected = file_bytes(folder.path() / ("serialized_" + name));
        EXPECT_FALSE(expected.empty());
        EXPECT_EQ(file_bytes(folder.path() / ("pipelined_" + name)), expected) << name;
        EXPECT_EQ(pipelined[i].ssr_counts->failed, serialized[i].ssr_counts->failed) << name;
        if (mode == render::ReflectionMode::hybrid) {
          EXPECT_EQ(pipelined[i].ray_stats->rays_traced, serialized[i].ray_stats->rays_traced) << name;
        }
      }
      // Consecutive frames differ (the camera moves), so a frame read from the wrong slot shows.
      EXPECT_NE(pipelined[0].final_image->pixels, pipelined[1].final_image->pixels);
    }
  }
}

// The captured image is the one read_final() returns after the frame (the pipeline's own readback).
TEST_F(PipelinedFrameLoop, CapturedImageIsTheFinalImage) {
  Scene scene = make_preset("atrium-simple");
  FrameLoopOptions options{kWidth, kHeight};
  options.capture_final = true;
  FrameLoop loop(scene, settings_for(render::ReflectionMode::ssr), options, PassTimingMethod::gpu_queries);
  const FrameMeasurement measured = loop.run(2100);
  ASSERT_TRUE(measured.final_image.has_value());
  EXPECT_EQ(measured.final_image->pixels, loop.pipeline().read_final().pixels);
}

TEST(ImageWriterThread, WritesEveryQueuedFileWhole) {
  TempFolder folder;
  ImageRgba8 image(7, 5, glm::u8vec4(10, 20, 30, 255));
  {
    ImageWriterThread writer(1, 3);  // a queue of one: write() waits for the workers
    for (int i = 0; i < 6; ++i) {
      image.at(i, 0) = glm::u8vec4(200, 0, 0, 255);
      writer.write(folder.path() / ("image_" + std::to_string(i) + ".png"), image);
    }
    writer.finish();
  }
  for (int i = 0; i < 6; ++i) {
    const ImageRgba8 read = read_png(folder.path() / ("image_" + std::to_string(i) + ".png"));
    ASSERT_EQ(read.width, 7);
    EXPECT_EQ(read.at(i, 0), glm::u8vec4(200, 0, 0, 255));
    EXPECT_EQ(read.at(6, 4), glm::u8vec4(10, 20, 30, 255));
  }
  for (const auto& entry : fs::directory_iterator(folder.path()))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary left behind: " << entry.path();
}

TEST(ImageWriterThread, AFailedWriteIsOneErrorNamingTheFile) {
  TempFolder folder;
  const fs::path missing = folder.path() / "no_such_folder" / "frame_00001.png";
  ImageWriterThread writer;
  writer.write(missing, ImageRgba8(4, 4, glm::u8vec4(1)));
  try {
    writer.finish();
    FAIL() << "finish() must report the failed write";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("frame_00001.png"), std::string::npos) << error.what();
    EXPECT_EQ(std::string(error.what()).find('\n'), std::string::npos) << "one line";
  }
  EXPECT_THROW(writer.write(folder.path() / "later.png", ImageRgba8(4, 4)), Error) << "later writes fail too";
  EXPECT_FALSE(fs::exists(folder.path() / "later.png"));
}

}  // namespace
}  // namespace glint
