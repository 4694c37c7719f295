// Scene files with repeated keys, huge strings and control characters: errors that name the file and
// the place, with the file's strings shown bounded and escaped.
#include "core/error.h"
#include "scene/json_field.h"
#include "scene/scene_json_parser.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

using testing::error_of;

std::string parse_error(const std::string& text) {
  return error_of([&] { parse_scene_description(text, "room.scene.json"); });
}

TEST(SceneJsonHostileInput, DuplicateKeysAreErrorsWithLineColumnAndKey) {
  // Before, the last "frames" silently won.
  EXPECT_EQ(parse_error("{\n  \"frames\": 10,\n  \"meshes\": [{\"file\": \"a.obj\"}],\n  \"frames\": 20\n}"),
            "room.scene.json:4:3: duplicate key \"frames\" (each key may appear once per object)");
  // In a nested object, with an escaped quote in the key; the same key in sibling objects is fine.
  const std::string nested = R"({"meshes": [{"file": "a.obj", "name": "x"}, {"file": "b.obj", "transform": {"scale": 2, "sc\"ale": 1, "sc\"ale": 3}}]})";
  EXPECT_EQ(parse_error(nested), "room.scene.json:1:103: duplicate key \"sc\"ale\" (each key may appear once per object)");
  EXPECT_EQ(nested.substr(102, 8), R"("sc\"ale)");
  EXPECT_NO_THROW(parse_scene_description(R"({"meshes": [{"file": "a.obj"}, {"file": "b.obj"}]})", "ok.scene.json"));
}

TEST(SceneJsonHostileInput, HugeStringsAndControlCharactersAreBoundedAndEscapedInErrors) {
  const std::string huge(5'000'000, 'a');  // the report's was 50 MB; 5 MB shows the same
  for (const std::string& text :
       {R"({"meshes": [{"file": "m.obj", "deform": {"type": ")" + huge + R"("}}]})",  // echoed value
        R"({"meshes": [{"file": "m.obj", ")" + huge + R"(": 1}]})",                    // echoed key
        R"({"meshes": [{"file": ")" + huge + R"(.obj"}]})",                             // a path no system opens
        R"({"meshes": [{"file": "m.obj"}], "frames": ")" + huge}) {                  // parser's "last read"
    const std::string message = parse_error(text);
    EXPECT_EQ(message.rfind("room.scene.json", 0), 0u) << message.substr(0, 300);
    EXPECT_LT(message.size(), 1000u) << message.substr(0, 300);
    EXPECT_NE(message.find("bytes in all)"), std::string::npos) << message.substr(0, 300);
  }
  const std::string escaped = parse_error("{\"meshes\": [{\"file\": \"a\\u001b[2J.obj\"}]}");
  EXPECT_NE(escaped.find("/meshes/0/file: the file name \"a\\x1b[2J.obj\" contains control characters"),
            std::string::npos)
      << escaped;
  const std::string axis = parse_error(
      "{\"meshes\": [{\"file\": \"m.obj\", \"deform\": {\"type\": \"sine\", \"axis\": \"\\n\\u0007\"}}]}");
  EXPECT_NE(axis.find("unknown axis \"\\n\\x07\""), std::string::npos) << axis;
}

}  // namespace
}  // namespace glint
