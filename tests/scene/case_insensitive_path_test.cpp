// Texture and library names written on the author's machine: case, backslashes, and absolute paths
// that only make sense there (C:\Users\...\Textures\wall.png gave a checker placeholder although
// Textures/wall.png was beside the MTL file).
#include "scene/case_insensitive_path.h"

#include "support/temp_folder.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(CaseInsensitivePath, CaseAndBackslashesAreForgiven) {
  testing::TempFolder folder;
  const auto wall = folder.write("textures/wall.png", "x");
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "Textures\\Wall.PNG"), wall);
}

TEST(CaseInsensitivePath, AnAbsolutePathFromAnotherMachineFindsItsTailBesideTheFolder) {
  testing::TempFolder folder;
  const auto wall = folder.write("Textures/wall.png", "x");
  const auto floor = folder.write("floor.png", "x");
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "C:\\Users\\me\\model\\textures\\wall.png"), wall);
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "/home/author/model/Textures/wall.png"), wall);
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "D:/assets/other/floor.png"), floor);
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "../elsewhere/FLOOR.png"), floor);
  // The longest tail wins: Textures/wall.png over a wall.png of the folder itself.
  folder.write("wall.png", "y");
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "C:\\model\\Textures\\wall.png"), wall);
}

TEST(CaseInsensitivePath, NothingFoundIsTheExactPath) {
  testing::TempFolder folder;
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "Textures/gone.png"), folder.path() / "Textures/gone.png");
  EXPECT_EQ(find_file_ignoring_case(folder.path(), "/abs/gone.png"), std::filesystem::path("/abs/gone.png"));
}

}  // namespace
}  // namespace glint
