// `glint render --backend gl` as a user runs it: the frame equals the cpu backend's (same BVHs, same
// triangle test, traced in GL compute shaders instead of on the CPU), run.json names the backend, and
// the GPU deformer (which writes the cuda backend's copies) is refused in one line. `glint bench`
// takes gl as an available backend with glint's builders.
#include "app/bench/backend_availability.h"
#include "app/bench/paper_matrix.h"
#include "app/cli_runner.h"
#include "backends/registry.h"
#include "core/image.h"
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

TEST_F(RenderCliGlBackend, GpuDeformationIsOneClearLine) {
  TempFolder folder;
  const fs::path out = folder.path() / "gl";
  const CliResult r = run_glint("render atrium-simple --frames 2100 --width 32 --height 18 --backend gl --deform-on gpu "
                                "--out " + quoted(out));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("--deform-on gpu needs --backend cuda or optix"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the gl backend"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
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
