// `glint render file.obj` of a file without mirrors (no MTL, or MTL materials without Pm / illum 3..7):
// every --reflections mode gave the same frames without a word; now one warning says why and how to
// give materials reflectivity. A file with a mirror, and --reflections off, stay quiet.
#include "app/cli_runner.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <string>

namespace glint::testing {
namespace {

using RenderCliNothingReflects = GlTest;  // skips without headless OpenGL 4.5

constexpr const char* kQuad = "v -1 0 1\nv 1 0 1\nv 1 0 -1\nv -1 0 -1\nf 1 2 3 4\n";

CliResult render(const TempFolder& folder, const std::string& obj, const std::string& reflections) {
  return run_glint("render " + quoted(folder.path() / obj) + " --reflections " + reflections +
                   " --frames 0 --width 16 --height 9 --out " + quoted(folder.path() / (obj + "-" + reflections)));
}

TEST_F(RenderCliNothingReflects, ABareObjIsOneWarningSayingHowToMakeItReflect) {
  TempFolder folder;
  folder.write("bare.obj", kQuad);
  folder.write("mirror.obj", std::string("mtllib m.mtl\nusemtl m\n") + kQuad);
  folder.write("m.mtl", "newmtl m\nKs 0.5 0.5 0.5\nillum 3\n");

  const CliResult bare = render(folder, "bare.obj", "hybrid");
  ASSERT_EQ(bare.exit_code, 0) << bare.err;
  EXPECT_NE(bare.err.find("bare.obj: no material reflects (every reflectivity is 0), so --reflections hybrid adds nothing"),
            std::string::npos)
      << bare.err;
  EXPECT_NE(bare.err.find("\"reflectivity\": 0.5"), std::string::npos) << bare.err;

  const CliResult off = render(folder, "bare.obj", "off");
  ASSERT_EQ(off.exit_code, 0) << off.err;
  EXPECT_EQ(off.err.find("no material reflects"), std::string::npos) << off.err;
  const CliResult mirror = render(folder, "mirror.obj", "rt");
  ASSERT_EQ(mirror.exit_code, 0) << mirror.err;
  EXPECT_EQ(mirror.err.find("no material reflects"), std::string::npos) << mirror.err;
}

}  // namespace
}  // namespace glint::testing
