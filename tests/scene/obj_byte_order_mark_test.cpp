// OBJ and MTL files saved by Windows editors start with a UTF-8 byte order mark. It glued itself to
// the first statement: an OBJ whose first line is a vertex lost that vertex ("position 3 is out of
// range (2 defined before this line)"), and an MTL lost its first `newmtl` ("'Kd' before any 'newmtl'").
#include "scene/obj_loader.h"

#include "core/log.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

const std::string kByteOrderMark = "\xEF\xBB\xBF";

TEST(ObjByteOrderMark, AnObjAndItsMtlStartingWithOneLoadAsWithout) {
  testing::TempFolder folder;
  folder.write("red.mtl", kByteOrderMark + "newmtl red\nKd 0.9 0.1 0.1\n");
  const auto obj = folder.write("tri.obj", kByteOrderMark + "v 0 0 0\nv 1 0 0\nv 0 1 0\nmtllib red.mtl\nusemtl red\nf 1 2 3\n");
  const ScopedLogCapture capture;
  const Scene scene = load_obj(obj);
  for (const auto& entry : capture.entries()) EXPECT_NE(entry.level, LogLevel::warning) << entry.message;
  ASSERT_EQ(scene.meshes.size(), 1u);
  EXPECT_EQ(scene.meshes[0].positions[0], vec3(0, 0, 0));
  ASSERT_EQ(scene.materials.size(), 1u);
  EXPECT_EQ(scene.materials[0].name, "red");
  EXPECT_EQ(scene.materials[0].diffuse, vec3(0.9f, 0.1f, 0.1f));
}

TEST(ObjByteOrderMark, LinesAreStillCountedFromTheFirst) {
  testing::TempFolder folder;
  const auto obj = folder.write("bad.obj", kByteOrderMark + "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  const ScopedLogCapture quiet;
  const std::string message = testing::error_of([&] { load_obj(obj); });
  EXPECT_NE(message.find("bad.obj:3: '3': position 3 is out of range (2 defined before this line)"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace glint
