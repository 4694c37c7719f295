// `glint render --backend gl` as a user runs it: the frame equals the cpu backend's (same BVHs, same
// triangle test, traced in GL compute shaders instead of on the CPU), run.json names the backend;
// --deform-on gpu (the default with --update refit) poses the meshes in GL and refits the structures
// in GL compute, and its frames equal --deform-on cpu's; rebuild and auto with it are refused in one
// line. `glint bench` takes gl as an available backend with glint's builders.
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
// structures: a refit that did not follow the meshes would draw the dinosaurs at rest.
TEST_F(RenderCliGlBackend, GpuDeformationRefitsOnTheGpuAndDrawsTheCpuDeformersFrames) {
  TempFolder folder;
  const std::string render = "render atrium-simple --reflections rt --primary rt --shadows rt --frames 2100:2101 "
                             "--width 160 --height 90 --backend gl ";
  // --deform-on left out with --update refit: gpu, the gl backend's default there.
  for (const char* run : {"gpu", "cpu", "off"}) {
    const std::string flags = std::string(run) == "gpu"   ? "--update refit"
                              : std::string(run) == "cpu" ? "--update refit --deform-on cpu"
                                                          : "--deform off";
    const CliResult r = run_glint(render + flags + " --out " + quoted(folder.path() / run));
    ASSERT_EQ(r.exit_code, 0) << run << ": " << r.err;
  }
  const nlohmann::json run = nlohmann::json::parse(read_text_file(folder.path() / "gpu" / "run.json"));
  EXPECT_EQ(run["options"]["deform_on"], "gpu");
  EXPECT_EQ(run["ray_tracer"]["refits"], 4) << "two frames of the two deforming meshes, refitted on the GPU";
  const auto luma_ssim = [&](const char* a, const char* b) {
    return metrics::colour_ssim(read_png(folder.path() / a / "frame_02101.png"),
                                read_png(folder.path() / b / "frame_02101.png"))
        .luma;
  };
  // GL's sin is not the host's: positions agree to about 1e-5 of the extent (GlSceneDeformerTest),
  // which may move an edge across a pixel centre. Identical on llvmpipe (SSIM 1).
  EXPECT_GE(luma_ssim("gpu", "cpu"), 0.999);
  // The meshes at rest differ visibly (measured on llvmpipe: 0.9961).
  EXPECT_LT(luma_ssim("gpu", "off"), 0.999);
}

TEST_F(RenderCliGlBackend, GpuDeformationWithRebuildingPoliciesIsOneClearLine) {
  TempFolder folder;
  const fs::path out = folder.path() / "gl";
  for (const char* update : {"auto", "rebuild"}) {
    const CliResult r = run_glint(std::string("render atrium-simple --frames 2100 --width 32 --height 18 --backend gl "
                                              "--deform-on gpu --update ") +
                                  update + " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 1) << update;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--deform-on gpu with --backend gl refits on the GPU, but --update " + std::string(update)),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("use --update refit or --deform-on cpu"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << update;
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
