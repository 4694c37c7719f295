// `glint render --backend gl` as a user runs it: the frame equals the cpu backend's (same BVHs, same
// triangle test, traced in GL compute shaders instead of on the CPU), run.json names the backend;
// --deform-on gpu (its default under every --update) poses the meshes in GL and refits the structures
// in GL compute (auto: rebuilds past the SAH ratio measured in GL compute; rebuild: every frame, on the
// host from the positions read back), and its frames equal --deform-on cpu's. `glint bench` takes gl as
// an available backend with glint's builders.
#include "app/bench/backend_availability.h"
#include "app/bench/paper_matrix.h"
#include "app/cli_runner.h"
#include "backends/registry.h"
#include "core/image.h"
#include "metrics/ssim.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using RenderCliGlBackend = GlTest;

TEST_F(RenderCliGlBackend, HybridFrameEqualsTheCpuBackendsFrame) {
  TempFolder folder;
  for (const char* backend : {"gl", "cpu"}) {
    const CliResult r = run_glint(std::string("render atrium-simple --reflections hybrid --frames 2100 --width 64 "
                                              "--height 36 --backend ") +
                                  backend + " --out " + quoted(folder.path() / backend));
    ASSERT_EQ(r.exit_code, 0) << backend << ": " << r.err;
  }
  const nlohmann::json run = nlohmann::json::parse(read_text_file(folder.path() / "gl" / "run.json"));
  EXPECT_EQ(run["ray_tracer"]["backend"], "gl");
  const auto csv = read_csv(folder.path() / "gl" / "timings.csv");
  ASSERT_EQ(csv.size(), 2u);
  EXPECT_GT(std::stoi(csv[1][17]), 0) << csv[0][17];  // rays_traced: the reflections did trace

  const ImageRgba8 gl = read_png(folder.path() / "gl" / "frame_02100.png");
  const ImageRgba8 cpu = read_png(folder.path() / "cpu" / "frame_02100.png");
  ASSERT_EQ(gl.pixels.size(), cpu.pixels.size());
  size_t different = 0;
  for (size_t i = 0; i < gl.pixels.size(); ++i) different += gl.pixels[i] != cpu.pixels[i] ? 1 : 0;
  // Equal on llvmpipe; a GPU's division rounding may flip a hit on a shared edge, so a few pixels may differ.
  EXPECT_LE(different, gl.pixels.size() / 200) << different << " pixels differ";
}

// Camera rays, reflections and shadows all traced (--primary rt), so every pixel shows the tracer's
// structures: structures that did not follow the meshes (a refit or a rebuild from the host's rest
// positions) would draw the dinosaurs at rest. Under every --update the gl backend deforms on the GPU
// by default: refit refits in GL compute, auto too (rebuilding past the SAH ratio), rebuild rebuilds
// on the host from the positions read back.
TEST_F(RenderCliGlBackend, GpuDeformationRefitsOnTheGpuAndDrawsTheCpuDeformersFrames) {
  TempFolder folder;
  const std::string render = "render atrium-simple --reflections rt --primary rt --shadows rt --frames 2100:2101 "
                             "--width 160 --height 90 --backend gl ";
  for (const char* run : {"refit", "auto", "rebuild", "cpu", "off"}) {
    const std::string name(run);
    const std::string flags = name == "cpu" ? "--update refit --deform-on cpu"
                              : name == "off" ? "--deform off"
                                              : "--update " + name;  // --deform-on left out: gpu
    const CliResult r = run_glint(render + flags + " --out " + quoted(folder.path() / run));
    ASSERT_EQ(r.exit_code, 0) << run << ": " << r.err;
  }
  const auto tracer_of = [&](const char* run) {
    const nlohmann::json json = nlohmann::json::parse(read_text_file(folder.path() / run / "run.json"));
    EXPECT_EQ(json["options"]["deform_on"], "gpu") << run;
    return json["ray_tracer"];
  };
  // Two frames of the two deforming meshes.
  EXPECT_EQ(tracer_of("refit")["refits"], 4) << "refitted on the GPU";
  const nlohmann::json automatic = tracer_of("auto");
  EXPECT_EQ(automatic["refits"].get<int>() + automatic["rebuilds"].get<int>(), 4) << automatic.dump();
  EXPECT_TRUE(automatic.contains("final_blas_sah_drift")) << "measured on the GPU: " << automatic.dump();
  EXPECT_EQ(tracer_of("rebuild")["rebuilds"], 4);
  const auto luma_ssim = [&](const char* a, const char* b) {
    return metrics::colour_ssim(read_png(folder.path() / a / "frame_02101.png"),
                                read_png(folder.path() / b / "frame_02101.png"))
        .luma;
  };
  // GL's sin is not the host's: positions agree to about 1e-5 of the extent (GlSceneDeformerTest),
  // which may move an edge across a pixel centre. Identical on llvmpipe (SSIM 1).
  for (const char* update : {"refit", "auto", "rebuild"}) EXPECT_GE(luma_ssim(update, "cpu"), 0.999) << update;
  // The meshes at rest differ visibly (measured on llvmpipe: 0.9961).
  EXPECT_LT(luma_ssim("refit", "off"), 0.999);
}

// --update auto and rebuild deform on the GPU too by default: auto measures the SAH cost in GL compute
// and rebuilds past its ratio, rebuild rebuilds every frame on the host from the positions read back;
// the frames equal --deform-on cpu's (the host deforming, building and uploading).
TEST_F(RenderCliGlBackend, GpuDeformationUnderAutoAndRebuildDrawsTheCpuDeformersFrames) {
  TempFolder folder;
  const std::string render = "render atrium-simple --backend gl --reflections hybrid --width 96 --height 54 "
                             "--frames 1800:1801 --update ";
  for (const char* update : {"auto", "rebuild"}) {
    const fs::path gpu = folder.path() / (std::string(update) + "-gpu");
    const fs::path cpu = folder.path() / (std::string(update) + "-cpu");
    CliResult r = run_glint(render + update + " --out " + quoted(gpu));
    ASSERT_EQ(r.exit_code, 0) << update << ": " << r.err;
    r = run_glint(render + update + " --deform-on cpu --out " + quoted(cpu));
    ASSERT_EQ(r.exit_code, 0) << update << ": " << r.err;
    const nlohmann::json run = nlohmann::json::parse(read_text_file(gpu / "run.json"));
    EXPECT_EQ(run["options"]["deform_on"], "gpu") << update;
    const nlohmann::json& tracer = run["ray_tracer"];
    // Two frames of the two deforming meshes.
    EXPECT_EQ(tracer["refits"].get<int>() + tracer["rebuilds"].get<int>(), 4) << update << ": " << tracer.dump();
    if (std::string(update) == "rebuild") {
      EXPECT_EQ(tracer["rebuilds"], 4) << tracer.dump();
    }
    for (const char* frame : {"frame_01800.png", "frame_01801.png"}) {
      // As GpuDeformationRefitsOnTheGpuAndDrawsTheCpuDeformersFrames: GL's sin is not the host's.
      EXPECT_GE(metrics::colour_ssim(read_png(gpu / frame), read_png(cpu / frame)).luma, 0.999)
          << update << " " << frame;
    }
  }
}

TEST(BenchGlBackend, IsAvailableWithGlintsBuilders) {
  // No GL context here: gl is made on the cells' context, so availability does not make one.
  EXPECT_FALSE(bench::backend_unavailable_reason("gl").has_value());
  EXPECT_TRUE(backends::find_backend("gl").takes_glint_builders);
  const std::vector<bench::Structure> structures = bench::structures_of({"gl"}, {"sah", "lbvh"});
  ASSERT_EQ(structures.size(), 2u);
  EXPECT_EQ(structures[1].label(), "gl-lbvh");
}

}  // namespace
}  // namespace glint::testing
