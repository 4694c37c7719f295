// `glint render` as a user runs it: the files it promises, their shapes, and one-line errors that
// leave nothing behind.
#include "app/cli_runner.h"
#include "app/video_writer.h"
#include "cuda/device_query.h"
#include "core/image.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

// GlTest skips every test when this machine has no headless OpenGL 4.5 (the command would fail).
using RenderCli = GlTest;

TEST_F(RenderCli, WritesFramesDebugViewsTimingsRunRecordAndVideo) {
  TempFolder folder;
  const fs::path out = folder.path() / "run";
  const bool video = find_program_on_path("ffmpeg").has_value();
  const CliResult r = run_glint("render atrium-simple --width 64 --height 36 --frames 2100:2101 --debug-views --out " +
                                quoted(out) + (video ? " --video" : ""));
  ASSERT_EQ(r.exit_code, 0) << r.err;

  for (const char* frame : {"frame_02100", "frame_02101"}) {
    const ImageRgba8 image = read_png(out / (std::string(frame) + ".png"));
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 36);
    for (const char* view : {"albedo", "normals", "positions", "depth", "shadow_mask", "ssr_reflection", "failure_mask",
                             "traced_reflection", "reflection"})
      EXPECT_TRUE(fs::exists(out / (std::string(frame) + "_" + view + ".png"))) << frame << " " << view;
  }
  if (video) {
    EXPECT_GT(fs::file_size(out / "walkthrough.mp4"), 0u);
  }

  const auto csv = read_csv(out / "timings.csv");
  ASSERT_EQ(csv.size(), 3u) << "header + one row per frame";
  const std::vector<std::string> header = {
      "frame",        "shadow_ms",       "gbuffer_ms", "light_ms",  "ssr_ms",            "ray_list_ms",
      "hit_shade_ms", "resolve_ms",      "gpu_total_ms", "frame_ms", "frame_latency_ms", "deform_ms", "accel_update_ms",
      "trace_ms",     "triangles",       "reflective_pixels", "ssr_failed_pixels", "rays_traced",
      "resident_mb",  "gpu_memory_used_mb", "classify_ms", "tiles_none", "tiles_ssr_only", "tiles_ssr_fallback",
      "tiles_rt_only", "ray_budget", "budget_factor", "rays_wanted", "hit_shadow_trace_ms"};
  EXPECT_EQ(csv[0], header);
  EXPECT_EQ(csv[1][0], "2100");
  EXPECT_EQ(csv[2][0], "2101");
  for (std::size_t row = 1; row < csv.size(); ++row) {
    ASSERT_EQ(csv[row].size(), header.size());
    // Up to resident_mb: GPU memory (NVIDIA only) and --reflections auto's columns are empty here.
    for (std::size_t column = 1; column < 19; ++column)
      EXPECT_GE(std::stod(csv[row][column]), 0.0) << header[column];
    EXPECT_GT(std::stod(csv[row][18]), 10.0) << "a GL process holds more than 10 MiB";
    if (!csv[row][19].empty()) {
      EXPECT_GT(std::stod(csv[row][19]), 0.0) << "GPU memory in use (NVIDIA only)";
    }
    EXPECT_GT(std::stod(csv[row][9]), 0.0) << "frame_ms";
    EXPECT_GT(std::stod(csv[row][10]), 0.0) << "frame_latency_ms";
    EXPECT_LE(std::stoul(csv[row][16]), std::stoul(csv[row][15])) << "failed pixels are reflective pixels";
    EXPECT_EQ(csv[row][17], csv[row][16]) << "hybrid traces exactly the failed pixels";
  }

  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_FALSE(run["gl"]["renderer"].get<std::string>().empty());
  EXPECT_EQ(run["resolution"], nlohmann::json::array({64, 36}));
  EXPECT_EQ(run["frames"]["count"], 2);
  EXPECT_EQ(run["frames_rendered"], 2);
  EXPECT_EQ(run["options"]["reflections"], "hybrid") << "the default mode";
  EXPECT_EQ(run["ray_tracer"]["backend"], "cpu");
  EXPECT_EQ(run["ray_tracer"]["accel"], "sah");
  EXPECT_EQ(run["ray_tracer"]["update"], "auto");
  EXPECT_GT(run["ray_tracer"]["memory_bytes"].get<double>(), 0.0);
  EXPECT_EQ(run["ray_tracer"]["rebuilds"].get<int>() + run["ray_tracer"]["refits"].get<int>(), 2 * 2)
      << "two deforming dinosaurs, updated at each of the two frames";
  EXPECT_EQ(run["scene"]["name"], "atrium-simple");
  // The paper's fade, which the atrium presets keep (render/scene_reflection_fade.h).
  EXPECT_EQ(run["scene"]["reflection_fade"]["start"], 15.0);
  EXPECT_EQ(run["scene"]["reflection_fade"]["end"], 30.0);
  EXPECT_EQ(run["scene"]["reflection_fade"]["from"], "the scene");
  EXPECT_NE(run["command"].get<std::string>().find("render atrium-simple"), std::string::npos);

  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary left behind: " << entry.path();
}

TEST_F(RenderCli, ReflectionsOffLeavesTheSsrColumnsEmptyAndTimingsOnlyWritesNoImages) {
  TempFolder folder;
  const fs::path out = folder.path() / "off";
  // Cube shadows: no ray tracer at all (rt shadows, the default, build one in every reflection mode).
  const CliResult r = run_glint("render atrium-simple --reflections off --shadows cube --timings-only --width 32 --height 18 "
                                "--frames 0 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_NE(entry.path().extension(), ".png") << entry.path();
  EXPECT_TRUE(fs::exists(out / "run.json"));
  const auto csv = read_csv(out / "timings.csv");
  ASSERT_EQ(csv.size(), 2u);
  ASSERT_EQ(csv[1].size(), 29u);
  for (const int column : {4, 5, 6, 12, 13, 15, 16, 17})
    EXPECT_EQ(csv[1][column], "") << "column " << column << " (no SSR, no ray tracing)";
}

TEST_F(RenderCli, RtModeWithEmbreeTracesEveryReflectivePixel) {
  TempFolder folder;
  const fs::path out = folder.path() / "rt";
  const CliResult r = run_glint("render atrium-simple --reflections rt --backend embree --update rebuild --timings-only "
                                "--width 48 --height 27 --frames 2100 --out " + quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto csv = read_csv(out / "timings.csv");
  ASSERT_EQ(csv.size(), 2u);
  ASSERT_EQ(csv[1].size(), 29u);
  EXPECT_EQ(csv[1][4], "") << "no SSR in rt mode";
  EXPECT_EQ(csv[1][16], "") << "no SSR failures in rt mode";
  EXPECT_GT(std::stoul(csv[1][17]), 0u);
  EXPECT_EQ(csv[1][17], csv[1][15]) << "rt traces every reflective pixel";
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["ray_tracer"]["backend"], "embree");
  EXPECT_EQ(run["ray_tracer"]["update"], "rebuild");
}

TEST_F(RenderCli, BadInputIsOneLineAndWritesNothing) {
  TempFolder folder;
  const fs::path out = folder.path() / "bad";
  const CliResult past_end = run_glint("render atrium-simple --frames 5000 --out " + quoted(out));
  EXPECT_EQ(past_end.exit_code, 1);
  EXPECT_EQ(line_count(past_end.err), 1) << past_end.err;
  EXPECT_NE(past_end.err.find("5000"), std::string::npos) << past_end.err;
  EXPECT_FALSE(fs::exists(out)) << "no output folder for a run that never started";

  EXPECT_EQ(run_glint("render atrium-simple --reflections maybe --out " + quoted(out)).exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --width 0 --out " + quoted(out)).exit_code, 2);
  // SSR's thickness is a fraction of the view depth, (0, 1].
  EXPECT_EQ(run_glint("render atrium-simple --ssr-thickness 2 --out " + quoted(out)).exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --ssr-thickness 0 --out " + quoted(out)).exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --frames 3:1 --out " + quoted(out)).exit_code, 1);
  EXPECT_EQ(run_glint("render atrium-simple --backend optix9 --out " + quoted(out)).exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --accel octree --out " + quoted(out)).exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --update sometimes --out " + quoted(out)).exit_code, 2);
  EXPECT_EQ(run_glint("render atrium-simple --deform-on tpu --out " + quoted(out)).exit_code, 2);
  for (const char* conflict : {"--backend embree --accel lbvh", "--accel sbvh --update refit",
                               "--backend cuda --accel sbvh --update auto", "--deform-on gpu --backend cpu",
                               "--deform-on gpu --backend embree --reflections rt"}) {
    const CliResult r = run_glint(std::string("render atrium-simple ") + conflict + " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 1) << conflict;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << conflict;
  }
  const CliResult gpu_deform = run_glint("render atrium-simple --deform-on gpu --backend cpu --out " + quoted(out));
  EXPECT_NE(gpu_deform.err.find("--backend gl, cuda"), std::string::npos) << gpu_deform.err;
  const CliResult missing = run_glint("render /nonexistent/scene.obj --out " + quoted(out));
  EXPECT_EQ(missing.exit_code, 1);
  EXPECT_NE(missing.err.find("/nonexistent/scene.obj"), std::string::npos);
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(RenderCli, CudaBackendWithoutAGpuIsOneClearLine) {
  if (cuda_gpu_present()) GTEST_SKIP() << "this machine has a CUDA GPU (the cuda backend runs instead)";
  TempFolder folder;
  const fs::path out = folder.path() / "cuda";
  for (const char* flags : {"--backend cuda"}) {
    const CliResult r = run_glint(std::string("render atrium-simple --frames 2100 --width 32 --height 18 ") + flags +
                                  " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 1) << flags;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("CUDA"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << flags;
  }
}

// Without a ray tracer (ssr reflections, cube shadows) --deform-on gpu needs no CUDA: GL alone poses
// its vertex buffer (GlSceneDeformer), on any OpenGL 4.5, and the frames are the CPU deformer's.
TEST_F(RenderCli, GpuDeformationWithoutRaysIsGlAloneAndDrawsTheCpuDeformersFrame) {
  TempFolder folder;
  std::map<std::string, fs::path> frames;
  for (const char* where : {"gpu", "cpu"}) {
    const fs::path out = folder.path() / where;
    const CliResult r = run_glint(std::string("render atrium --frames 2100 --width 160 --height 90 --reflections ssr "
                                              "--shadows cube --deform on --deform-on ") +
                                  where + " --out " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << where << ": " << r.err;
    frames[where] = out / "frame_02100.png";
  }
  // Pixels more than 8 levels apart (largest channel). The two deformers' positions differ by an ulp
  // (GlSceneDeformerTest), which can move a triangle edge across a pixel centre: a few pixels.
  const auto differing = [](const ImageRgba8& a, const ImageRgba8& b) {
    int count = 0;
    for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
      const auto p = a.pixels[i], q = b.pixels[i];
      count += std::max({std::abs(p.x - q.x), std::abs(p.y - q.y), std::abs(p.z - q.z)}) > 8;
    }
    return count;
  };
  const ImageRgba8 gpu = read_png(frames["gpu"]), cpu = read_png(frames["cpu"]);
  ASSERT_EQ(gpu.pixels.size(), 160u * 90u);
  const int edge_flips = differing(gpu, cpu);
  EXPECT_LE(edge_flips, 160 * 90 / 500) << "GL's deformation against the CPU's (measured on llvmpipe: 3)";
  // Against the meshes at rest: the dinosaurs moved, so more pixels differ (measured: 53).
  const fs::path rest = folder.path() / "rest";
  ASSERT_EQ(run_glint("render atrium --frames 2100 --width 160 --height 90 --reflections ssr --shadows cube --deform "
                      "off --out " + quoted(rest)).exit_code, 0);
  EXPECT_GT(differing(read_png(rest / "frame_02100.png"), gpu), 3 * std::max(edge_flips, 5));
}

TEST_F(RenderCli, GpuDeformationWithACpuTracerIsOneClearLine) {
  // rt shadows (the default) build the --backend tracer in every reflection mode; a CPU tracer builds
  // from host vertices and cannot follow meshes the GPU deformed.
  TempFolder folder;
  const fs::path out = folder.path() / "gpu-deform";
  const CliResult r = run_glint("render atrium-simple --frames 2100 --width 32 --height 18 --reflections ssr "
                                "--deform-on gpu --out " + quoted(out));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--deform-on gpu needs --backend gl, cuda or optix when rays are traced"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace glint::testing
