// `glint render --accel sbvh|kdtree` on a scene without deforming meshes: nothing is ever refitted,
// so the default --update auto (and refit) must not be refused as they are for deforming meshes
// (render_cli_kdtree_test.cpp): they were, with "cannot follow the deforming meshes", for any scene.
#include "app/cli_runner.h"
#include "core/image.h"
#include "metrics/rmse_psnr.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using RenderCliStaticStructures = GlTest;  // skips without headless OpenGL 4.5

// A floor (reflectivity 0.5 through illum 3) and a box standing on it; nothing deforms.
constexpr const char* kObj =
    "mtllib s.mtl\n"
    "v -4 0 4\nv 4 0 4\nv 4 0 -4\nv -4 0 -4\n"
    "v -1 0 1\nv 1 0 1\nv 1 2 1\nv -1 2 1\nv -1 0 -1\nv 1 0 -1\nv 1 2 -1\nv -1 2 -1\n"
    "usemtl floor\nf 1 2 3 4\n"
    "usemtl box\nf 5 6 7 8\nf 6 10 11 7\nf 10 9 12 11\nf 9 5 8 12\nf 8 7 11 12\n";
constexpr const char* kMtl = "newmtl floor\nKd 0.6 0.6 0.6\nKs 0.5 0.5 0.5\nillum 3\nnewmtl box\nKd 0.8 0.2 0.1\n";

TEST_F(RenderCliStaticStructures, SbvhAndKdTreeRenderAStaticSceneWithEveryUpdatePolicy) {
  TempFolder folder;
  const fs::path obj = folder.write("s.obj", kObj);
  folder.write("s.mtl", kMtl);
  const std::string common = "render " + quoted(obj) + " --reflections rt --frames 0 --width 32 --height 18 --camera 0,1.5,5 --target 0,0.5,0";
  const CliResult reference = run_glint(common + " --accel sah --out " + quoted(folder.path() / "sah"));
  ASSERT_EQ(reference.exit_code, 0) << reference.err;
  const ImageRgba8 sah = read_png(folder.path() / "sah" / "frame_00000.png");
  for (const char* accel : {"sbvh", "kdtree"}) {
    for (const char* update : {"auto", "refit"}) {
      const fs::path out = folder.path() / (std::string(accel) + "-" + update);
      const CliResult r = run_glint(common + " --accel " + accel + " --update " + update + " --out " + quoted(out));
      ASSERT_EQ(r.exit_code, 0) << accel << " " << update << ": " << r.err;
      EXPECT_GE(metrics::rmse_psnr(read_png(out / "frame_00000.png"), sah).psnr, 50.0) << accel << " " << update;
    }
  }
}

}  // namespace
}  // namespace glint::testing
