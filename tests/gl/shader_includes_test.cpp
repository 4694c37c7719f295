#include "gl/shader_includes.h"

#include <gtest/gtest.h>

#include "support/error_of.h"

#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace glint {
namespace {

using testing::error_of;

// An in-memory shader root: include name -> source.
struct FakeRoot {
  std::map<std::string, std::string, std::less<>> files;
  ShaderIncludeLookup lookup() const {
    return [this](std::string_view name) -> std::optional<std::string_view> {
      const auto found = files.find(name);
      if (found == files.end()) return std::nullopt;
      return std::string_view(found->second);
    };
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream stream(text);
  for (std::string line; std::getline(stream, line);) lines.push_back(line);
  return lines;
}

// Replays the expanded text the way a GLSL compiler numbers it (`#line L S`: the next line is line L
// of source string S) and checks that every line the compiler sees is the very line of the file its
// (string, line) names: this is what makes the driver's error locations point at the right file.
void expect_lines_map_back(const ExpandedShaderSource& expanded, const std::map<std::string, std::string>& sources) {
  std::size_t string_number = 0;
  int line = 1;
  for (const std::string& text : lines_of(expanded.text)) {
    int new_line = 0, new_string = 0;
    if (std::sscanf(text.c_str(), "#line %d %d", &new_line, &new_string) == 2) {
      line = new_line;
      string_number = static_cast<std::size_t>(new_string);
      continue;
    }
    ASSERT_LT(string_number, expanded.files.size()) << text;
    const std::vector<std::string> original = lines_of(sources.at(expanded.files[string_number]));
    ASSERT_LE(line, static_cast<int>(original.size())) << expanded.files[string_number] << " text: " << text;
    const std::string& expected = original[static_cast<std::size_t>(line - 1)];
    if (text.rfind("// #include", 0) == 0)  // a skipped (already included) include stands on its own line
      EXPECT_NE(expected.find("#include"), std::string::npos) << expanded.files[string_number] << ":" << line;
    else
      EXPECT_EQ(text, expected) << expanded.files[string_number] << ":" << line;
    ++line;
  }
}

TEST(ShaderIncludes, SourceWithoutIncludesIsUnchanged) {
  const FakeRoot root;
  const std::string source = "#version 450 core\nvoid main() {}\n";
  const ExpandedShaderSource expanded = expand_shader_includes("a.comp.glsl", source, root.lookup(), "shaders/");
  EXPECT_EQ(expanded.text, source);
  EXPECT_EQ(expanded.files, std::vector<std::string>{"shaders/a.comp.glsl"});
}

TEST(ShaderIncludes, ExpandsRecursivelyWithLineDirectives) {
  FakeRoot root;
  root.files["include/a.glsl"] = "// a\n#include \"include/b.glsl\"\nfloat a() { return b(); }\n";
  root.files["include/b.glsl"] = "float b() { return 1.0; }";  // no final newline
  const std::string top = "#version 450 core\n  #  include \"include/a.glsl\"  // why\nvoid main() {}\n";
  const ExpandedShaderSource expanded = expand_shader_includes("top.comp.glsl", top, root.lookup());
  EXPECT_EQ(expanded.text,
            "#version 450 core\n"
            "#line 1 1\n"
            "// a\n"
            "#line 1 2\n"
            "float b() { return 1.0; }\n"
            "#line 3 1\n"
            "float a() { return b(); }\n"
            "#line 3 0\n"
            "void main() {}\n");
  EXPECT_EQ(expanded.files, (std::vector<std::string>{"top.comp.glsl", "include/a.glsl", "include/b.glsl"}));
}

TEST(ShaderIncludes, EachFileIsExpandedOnce) {
  FakeRoot root;
  root.files["include/common.glsl"] = "const float kOne = 1.0;\n";
  root.files["include/x.glsl"] = "#include \"include/common.glsl\"\nfloat x() { return kOne; }\n";
  root.files["include/y.glsl"] = "#include \"include/common.glsl\"\nfloat y() { return kOne; }\n";
  const std::string top =
      "#version 450 core\n#include \"include/x.glsl\"\n#include \"include/y.glsl\"\n"
      "#include \"include/x.glsl\"\nvoid main() {}\n";
  const ExpandedShaderSource expanded = expand_shader_includes("top.frag.glsl", top, root.lookup());
  std::size_t count = 0;
  for (std::size_t at = expanded.text.find("const float kOne"); at != std::string::npos;
       at = expanded.text.find("const float kOne", at + 1))
    ++count;
  EXPECT_EQ(count, 1u) << expanded.text;
  EXPECT_NE(expanded.text.find("float x()"), std::string::npos);
  EXPECT_NE(expanded.text.find("float y()"), std::string::npos);
  EXPECT_EQ(expanded.text.find("float x()"), expanded.text.rfind("float x()")) << expanded.text;
  EXPECT_EQ(expanded.files.size(), 4u);  // top, x, common, y: each one source-string number

  std::map<std::string, std::string> sources(root.files.begin(), root.files.end());
  sources["top.frag.glsl"] = top;
  expect_lines_map_back(expanded, sources);
}

TEST(ShaderIncludes, EveryExpandedLineMapsBackToItsFileAndLine) {
  FakeRoot root;
  root.files["include/a.glsl"] = "// a1\n#include \"include/b.glsl\"\n// a3\n#include \"include/c.glsl\"\n// a5\n";
  root.files["include/b.glsl"] = "// b1\n// b2\n#include \"include/c.glsl\"\n// b4\n";
  root.files["include/c.glsl"] = "// c1\n\n// c3\n";
  const std::string top =
      "#version 450 core\n// t2\n#include \"include/a.glsl\"\n// t4\n#include \"include/b.glsl\"\n// t6\n";
  const ExpandedShaderSource expanded = expand_shader_includes("top.vert.glsl", top, root.lookup());
  std::map<std::string, std::string> sources(root.files.begin(), root.files.end());
  sources["top.vert.glsl"] = top;
  expect_lines_map_back(expanded, sources);
  EXPECT_EQ(expanded.files,
            (std::vector<std::string>{"top.vert.glsl", "include/a.glsl", "include/b.glsl", "include/c.glsl"}));
}

TEST(ShaderIncludes, UnknownFileNamesTheIncludingFileAndLine) {
  const FakeRoot root;
  const std::string message = error_of([&] {
    expand_shader_includes("lighting.comp.glsl", "#version 450 core\n\n#include \"include/nope.glsl\"\n",
                           root.lookup(), "shaders/");
  });
  EXPECT_NE(message.find("shaders/lighting.comp.glsl:3:"), std::string::npos) << message;
  EXPECT_NE(message.find("unknown include file \"include/nope.glsl\""), std::string::npos) << message;
}

TEST(ShaderIncludes, UnknownFileInsideAnIncludeNamesThatInclude) {
  FakeRoot root;
  root.files["include/a.glsl"] = "// one\n#include \"include/missing.glsl\"\n";
  const std::string message = error_of([&] {
    expand_shader_includes("t.frag.glsl", "#version 450 core\n#include \"include/a.glsl\"\n", root.lookup(),
                           "shaders/");
  });
  EXPECT_NE(message.find("shaders/include/a.glsl:2: unknown include file \"include/missing.glsl\""),
            std::string::npos)
      << message;
}

TEST(ShaderIncludes, MalformedIncludeLinesAreErrors) {
  const FakeRoot root;
  for (const char* line : {"#include", "#include include/a.glsl", "#include <include/a.glsl>", "#include \"\"",
                           "#include \"include/a.glsl", "#include \"include/a.glsl\" extra"}) {
    const std::string message = error_of([&] {
      expand_shader_includes("t.frag.glsl", std::string("#version 450 core\n").append(line).append("\n"),
                             root.lookup());
    });
    EXPECT_NE(message.find("t.frag.glsl:2: malformed #include"), std::string::npos) << line << " -> " << message;
  }
}

TEST(ShaderIncludes, CycleIsAnErrorShowingTheChain) {
  FakeRoot root;
  root.files["include/a.glsl"] = "#include \"include/b.glsl\"\n";
  root.files["include/b.glsl"] = "// b\n#include \"include/a.glsl\"\n";
  const std::string message = error_of([&] {
    expand_shader_includes("t.frag.glsl", "#version 450 core\n#include \"include/a.glsl\"\n", root.lookup());
  });
  EXPECT_NE(message.find("include/b.glsl:2: include cycle: include/a.glsl -> include/b.glsl -> include/a.glsl"),
            std::string::npos)
      << message;
  // A file including itself is the shortest cycle.
  root.files["include/self.glsl"] = "#include \"include/self.glsl\"\n";
  EXPECT_NE(error_of([&] {
              expand_shader_includes("t.frag.glsl", "#include \"include/self.glsl\"\n", root.lookup());
            }).find("include cycle"),
            std::string::npos);
}

// "d<i>.glsl", and a file of that name that includes the next one (built by appending: GCC 12 gives
// a false -Wrestrict on "literal" + std::string).
std::string depth_file(int i) { return std::string("d").append(std::to_string(i)).append(".glsl"); }
std::string include_line(const std::string& name) { return std::string("#include \"").append(name).append("\"\n"); }

TEST(ShaderIncludes, NestingDeeperThanTheLimitIsAnError) {
  FakeRoot root;
  for (int i = 0; i < kMaxShaderIncludeDepth + 2; ++i) root.files[depth_file(i)] = include_line(depth_file(i + 1));
  root.files[depth_file(kMaxShaderIncludeDepth + 2)] = "// bottom\n";
  const std::string message =
      error_of([&] { expand_shader_includes("d0.glsl", root.files[depth_file(0)], root.lookup()); });
  EXPECT_NE(message.find("nested deeper than"), std::string::npos) << message;

  // Exactly at the limit is fine.
  FakeRoot shallow;
  for (int i = 1; i < kMaxShaderIncludeDepth - 1; ++i) shallow.files[depth_file(i)] = include_line(depth_file(i + 1));
  shallow.files[depth_file(kMaxShaderIncludeDepth - 1)] = "// bottom\n";
  const ExpandedShaderSource expanded = expand_shader_includes("d0.glsl", "#include \"d1.glsl\"\n", shallow.lookup());
  EXPECT_EQ(expanded.files.size(), static_cast<std::size_t>(kMaxShaderIncludeDepth));
  EXPECT_NE(expanded.text.find("// bottom"), std::string::npos);
}

TEST(ShaderIncludes, IncludedFileMustNotDeclareVersion) {
  FakeRoot root;
  root.files["include/v.glsl"] = "// v\n#version 450 core\n";
  const std::string message = error_of([&] {
    expand_shader_includes("t.frag.glsl", "#version 450 core\n#include \"include/v.glsl\"\n", root.lookup());
  });
  EXPECT_NE(message.find("include/v.glsl:2: an included file must not declare #version"), std::string::npos)
      << message;
}

TEST(ShaderIncludes, OtherDirectivesPassThrough) {
  const FakeRoot root;
  const std::string source = "#version 450 core\n#define includes 1\n#includes_not_an_include\n#extension X : enable\n";
  EXPECT_EQ(expand_shader_includes("t.frag.glsl", source, root.lookup()).text, source);
}


TEST(ShaderDefines, GoRightAfterVersionAndKeepTheFilesLineNumbers) {
  const std::string_view defines[] = {"ONE_ROUND", "B_2"};
  const std::string text = add_shader_defines("#version 450 core\nfloat a;\nfloat b;\n", defines);
  EXPECT_EQ(text, "#version 450 core\n#define ONE_ROUND 1\n#define B_2 1\n#line 2 0\nfloat a;\nfloat b;\n");
  // Without defines the source is unchanged (no #line either).
  EXPECT_EQ(add_shader_defines("#version 450 core\nx\n", {}), "#version 450 core\nx\n");
}

TEST(ShaderDefines, NeedVersionFirstAndIdentifiers) {
  const std::string_view good[] = {"A"};
  EXPECT_NE(error_of([&] { add_shader_defines("// comment\n#version 450 core\n", good); }).find("#version line"),
            std::string::npos);
  for (const std::string_view bad : {"", "2A", "A B", "A\n#define C"}) {
    const std::string_view defines[] = {bad};
    EXPECT_NE(error_of([&] { add_shader_defines("#version 450 core\n", defines); }).find("not a GLSL identifier"),
              std::string::npos)
        << bad;
  }
}

}  // namespace
}  // namespace glint
