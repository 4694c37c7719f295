// `glint view --script`: the whole file is checked before anything runs, and a bad line is one error
// naming the file and its line.
#include "viewer/viewer_script.h"

#include "support/error_of.h"

#include <gtest/gtest.h>

namespace glint::viewer {
namespace {

using glint::testing::error_of;

std::vector<ScriptCommand> parse(const std::string& text) {
  return parse_viewer_script(text, "demo.txt", 4900, RenderOptions());
}

TEST(ViewerScript, ParsesEveryCommandSkippingCommentsAndBlanks) {
  const std::vector<ScriptCommand> commands = parse(
      "# a demo\n"
      "set reflections rt   # the reference\n"
      "\n"
      "set view failure_mask\n"
      "frame 2100\n"
      "camera 0,2,5 0,1,0\n"
      "path\n"
      "play\n"
      "wait 0.5\n"
      "pause\n"
      "screenshot out.png\n"
      "record start\n"
      "record stop\n"
      "record save flown.scene.json\n"
      "reload\n"
      "quit\n");
  ASSERT_EQ(commands.size(), 14u);
  EXPECT_EQ(commands[0].verb, ScriptVerb::set);
  EXPECT_EQ(commands[0].line, 2);
  EXPECT_EQ(commands[0].arguments, (std::vector<std::string>{"reflections", "rt"}));
  EXPECT_EQ(commands[2].verb, ScriptVerb::frame);
  EXPECT_EQ(commands[2].line, 5);
  EXPECT_EQ(commands[11].arguments, (std::vector<std::string>{"save=flown.scene.json"}));
  EXPECT_EQ(commands.back().verb, ScriptVerb::quit);
}

TEST(ViewerScript, ABadLineIsOneErrorNamingItsLine) {
  const struct {
    const char* text;
    const char* expected;
  } cases[] = {
      {"frame 1\nfly away\n", "demo.txt:2: unknown command \"fly\""},
      {"set reflections raytraced\n", "demo.txt:1: reflections: \"raytraced\" is not one of off, ssr, hybrid, rt"},
      {"\n\nframe 4900\n", "demo.txt:3: frame: 4900 is outside 0 to 4899"},
      {"frame 12.5\n", "demo.txt:1: frame: 12.5 is not a whole number"},
      {"wait\n", "demo.txt:1: wait takes 1 argument, got 0"},
      {"camera 1,2 0,0,0\n", "demo.txt:1: camera \"1,2\": expected x,y,z"},
      {"screenshot out.jpg\n", "demo.txt:1: screenshot: out.jpg does not end in .png"},
      {"screenshot no/such/folder/out.png\n", "demo.txt:1: screenshot: folder no/such/folder does not exist"},
      {"set view sideways\n", "demo.txt:1: view: \"sideways\" is not one of final"},
      {"set light off\n", "demo.txt:1: light: \"off\" is not follow or stay"},
      {"record pause\n", "demo.txt:1: record: \"pause\" is not start, stop or save=FILE"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string message = error_of([&] { parse(text); });
    EXPECT_TRUE(message.starts_with(expected)) << text << " -> " << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

// Settings are checked in combination where the script renders: an embree backend with a glint
// structure is refused at the screenshot that would have used it, before anything ran.
TEST(ViewerScript, SettingCombinationsAreCheckedWhereTheScriptRenders) {
  const std::string message = error_of([&] {
    parse("set backend embree\nset accel lbvh\nset reflections rt\nscreenshot a.png\n");
  });
  EXPECT_TRUE(message.starts_with("demo.txt:4: --accel lbvh applies to the cpu")) << message;
  EXPECT_NO_THROW(parse("set backend embree\nset accel lbvh\nset accel sah\nscreenshot a.png\n"));
}

}  // namespace
}  // namespace glint::viewer
