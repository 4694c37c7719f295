// `glint render --accel kdtree|none` as a user runs it: the kd-tree's frames (one SAH kd-tree per mesh
// under the TLAS) and brute force's (`none`) equal the sah BVH's frames (PSNR >= 50 dB) on the cpu
// backend, and on the cuda backend where there is a CUDA GPU (skipped elsewhere); refitting a kd-tree
// (--update refit or auto on deforming meshes) and the gl backend with kdtree are one line each.
#include "app/cli_runner.h"
#include "core/image.h"
#include "cuda/device_query.h"
#include "metrics/rmse_psnr.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using RenderCliKdTree = GlTest;  // skips without headless OpenGL 4.5

// Renders frame 2100 of atrium-simple with rt reflections (every reflective pixel traced) and rt
// shadows, the creatures deforming (rebuilt every frame), with `accel` on `backend`; returns the frame.
ImageRgba8 render_frame(const fs::path& folder, const std::string& backend, const std::string& accel,
                        const std::string& size) {
  const fs::path out = folder / (backend + "-" + accel + "-" + size.substr(size.rfind(' ') + 1));
  const CliResult r = run_glint("render atrium-simple --reflections rt --shadows rt --update rebuild --frames 2099:2100 " +
                                size + " --backend " + backend + " --accel " + accel + " --out " + quoted(out));
  EXPECT_EQ(r.exit_code, 0) << backend << " " << accel << ": " << r.err;
  const nlohmann::json run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["ray_tracer"]["backend"], backend);
  return read_png(out / "frame_02100.png");
}

void expect_same_frames(const std::string& backend) {
  TempFolder folder;
  const ImageRgba8 sah = render_frame(folder.path(), backend, "sah", "--width 64 --height 36");
  const ImageRgba8 kdtree = render_frame(folder.path(), backend, "kdtree", "--width 64 --height 36");
  const double kdtree_psnr = metrics::rmse_psnr(kdtree, sah).psnr;
  EXPECT_GE(kdtree_psnr, 50.0) << backend << " kdtree";
  // Brute force costs every triangle per ray: a smaller frame.
  const ImageRgba8 sah_small = render_frame(folder.path(), backend, "sah", "--width 24 --height 14");
  const ImageRgba8 none = render_frame(folder.path(), backend, "none", "--width 24 --height 14");
  const double none_psnr = metrics::rmse_psnr(none, sah_small).psnr;
  EXPECT_GE(none_psnr, 50.0) << backend << " none";
  std::printf("[ psnr     ] %s: kdtree %.2f dB, none %.2f dB against sah\n", backend.c_str(), kdtree_psnr, none_psnr);
}

TEST_F(RenderCliKdTree, KdTreeAndNoneFramesEqualSahFramesOnTheCpuBackend) { expect_same_frames("cpu"); }

TEST_F(RenderCliKdTree, KdTreeAndNoneFramesEqualSahFramesOnTheCudaBackend) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  expect_same_frames("cuda");
}

TEST(RenderCliKdTreeErrors, RefittingAKdTreeAndKdTreeOnTheGlBackendAreOneLineEach) {
  TempFolder folder;
  for (const char* update : {"refit", "auto"}) {
    const fs::path out = folder.path() / update;
    const CliResult r = run_glint(std::string("render atrium-simple --frames 0 --width 16 --height 9 --accel kdtree "
                                              "--update ") +
                                  update + " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 1) << update;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find("--accel kdtree cannot be refitted"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--update rebuild"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
  const fs::path out = folder.path() / "gl";
  const CliResult r = run_glint("render atrium-simple --frames 0 --width 16 --height 9 --backend gl --accel kdtree "
                                "--update rebuild --out " + quoted(out));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("the gl backend traces BVHs only"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace glint::testing
