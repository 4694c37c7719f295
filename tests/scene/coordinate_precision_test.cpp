// A model far from the origin against its size is read and drawn with few distinct float
// coordinates across it; loading it says so, once, naming the file (before, the only sign was
// "dropped N degenerate triangles", or nothing while the model rendered as blocks).
#include "scene/coordinate_precision.h"

#include "core/log.h"
#include "scene/load_scene.h"
#include "support/temp_folder.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

// A tetrahedron `size` across with its first corner at `at`.
std::string tetrahedron(double size, double at_x, double at_z) {
  std::string text;
  const double corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& c : corners) text += fmt::format("v {:.9g} {:.9g} {:.9g}\n", at_x + size * c[0], size * c[1], at_z + size * c[2]);
  return text + "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
}

std::vector<std::string> warnings_loading(const std::filesystem::path& path) {
  const ScopedLogCapture capture;
  load_scene(path.string());
  std::vector<std::string> warnings;
  for (const auto& entry : capture.entries())
    if (entry.level == LogLevel::warning) warnings.push_back(entry.message);
  return warnings;
}

TEST(CoordinatePrecision, ASmallModelFarFromTheOriginIsOneWarningNamingTheFile) {
  testing::TempFolder folder;
  // 0.25 across at 1e5, where floats are 1/128 apart: 32 steps across (the corners stay exact).
  const auto far = folder.write("far.obj", tetrahedron(0.25, 1.0e5, -1.0e5));
  const std::vector<std::string> warnings = warnings_loading(far);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("far.obj: 'far' is 0.25 units across but 1e+05 from the origin"), std::string::npos)
      << warnings[0];
  EXPECT_NE(warnings[0].find("32 steps across it"), std::string::npos) << warnings[0];
}

TEST(CoordinatePrecision, TheSameModelNearTheOriginOrLargeEnoughIsNoWarning) {
  testing::TempFolder folder;
  EXPECT_TRUE(warnings_loading(folder.write("near.obj", tetrahedron(0.25, 3.0, -2.0))).empty());
  EXPECT_TRUE(warnings_loading(folder.write("scaled.obj", tetrahedron(250.0, 3000.0, -2000.0))).empty());
  // 4 units across at 1e5: 512 steps, fine.
  EXPECT_TRUE(warnings_loading(folder.write("room.obj", tetrahedron(4.0, 1.0e5, -1.0e5))).empty());
}

TEST(CoordinatePrecision, CountsEveryCoarseInstanceAndNamesTheCoarsest) {
  Scene scene;
  scene.source = "placed.scene.json";
  Mesh mesh;
  mesh.positions = {vec3(0), vec3(0.5f, 0, 0), vec3(0, 0.5f, 0)};
  mesh.indices = {0, 1, 2};
  scene.meshes.push_back(mesh);
  scene.instances.push_back({"near", 0, glm::translate(mat4(1.0f), vec3(1, 0, 0))});
  scene.instances.push_back({"far", 0, glm::translate(mat4(1.0f), vec3(6.0e4f, 0, 0))});
  scene.instances.push_back({"farther", 0, glm::translate(mat4(1.0f), vec3(0, 0, -2.0e5f))});
  const ScopedLogCapture capture;
  warn_about_coarse_coordinates(scene);
  ASSERT_EQ(capture.entries().size(), 1u);
  const std::string& message = capture.entries()[0].message;
  EXPECT_NE(message.find("placed.scene.json: 'farther' is 0.5 units across"), std::string::npos) << message;
  EXPECT_NE(message.find("(2 of 3 instances are this coarse)"), std::string::npos) << message;
}

}  // namespace
}  // namespace glint
