// `glint info` end to end: the README's main job prints the paper's scene sizes, and --json is
// machine-readable with the same numbers.
#include "app/cli_runner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace glint::testing {
namespace {

TEST(CliInfo, AtriumJsonHasThePapersCountsAndTwoDeformableMeshes) {
  const CliResult r = run_glint("info atrium --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json info = nlohmann::json::parse(r.out);
  EXPECT_NEAR(info["vertices"].get<double>(), 330'000, 0.05 * 330'000);
  EXPECT_NEAR(info["triangles"].get<double>(), 618'000, 0.05 * 618'000);
  int deformable = 0;
  for (const auto& mesh : info["meshes"]) deformable += mesh["deformable"].get<bool>() ? 1 : 0;
  EXPECT_EQ(deformable, 2);
  EXPECT_EQ(info["walkthrough"]["frames"].get<int>(), 4900);
  EXPECT_GT(info["walkthrough"]["camera_path_length"].get<double>(), 10.0);
}

TEST(CliInfo, TextOutputShowsCountsBoundsLightAndPaths) {
  const CliResult r = run_glint("info atrium-simple");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* field : {"vertices", "triangles", "bounds", "deformable  2 meshes", "materials", "textures", "light",
                            "walkthrough 4900 frames", "path length"})
    EXPECT_NE(r.out.find(field), std::string::npos) << field << " missing from:\n" << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

}  // namespace
}  // namespace glint::testing

namespace glint::testing {
namespace {

TEST(CliDevices, JsonAccountsForCudaAndOpenGlEitherWay) {
  const CliResult r = run_glint("devices --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json devices = nlohmann::json::parse(r.out);
  // Each of CUDA and OpenGL is either listed or explained, never silently absent.
  EXPECT_TRUE(!devices["cuda"].empty() || devices.contains("cuda_unavailable")) << r.out;
  EXPECT_TRUE(devices.contains("opengl") != devices.contains("opengl_unavailable")) << r.out;
  if (devices.contains("opengl")) {
    EXPECT_FALSE(devices["opengl"]["renderer"].get<std::string>().empty());
  }
}

}  // namespace
}  // namespace glint::testing
