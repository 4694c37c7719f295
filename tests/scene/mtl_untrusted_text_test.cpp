// Names and numbers that OBJ and MTL files quote into warnings and errors go through untrusted_text
// (docs/reliability.md): an MTL's duplicate material name, a bad number in an MTL, an undefined
// `usemtl` name and a missing library's name reached the terminal with their escape sequences.
#include "scene/obj_loader.h"

#include "core/log.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

const std::string kEscape = "\x1b[2J";  // clears the screen when printed raw

void expect_escaped(const std::string& message) {
  EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
  EXPECT_NE(message.find("\\x1b[2J"), std::string::npos) << message;
}

TEST(MtlUntrustedText, NamesInWarningsAreEscaped) {
  testing::TempFolder folder;
  folder.write("m.mtl", "newmtl a" + kEscape + "\nKd 1 0 0\nnewmtl a" + kEscape + "\nKd 0 1 0\n");
  const auto obj = folder.write("m.obj", "mtllib m.mtl\nmtllib gone" + kEscape + ".mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl b" +
                                             kEscape + "\nf 1 2 3\n");
  const ScopedLogCapture capture;
  load_obj(obj);
  int warnings = 0;
  for (const auto& entry : capture.entries()) {
    if (entry.level != LogLevel::warning) continue;
    ++warnings;
    expect_escaped(entry.message);
  }
  EXPECT_EQ(warnings, 3);  // the duplicate, the missing library, the undefined name
}

TEST(MtlUntrustedText, ABadNumberInAnErrorIsEscaped) {
  testing::TempFolder folder;
  for (const std::string& statement : {"Kd 1 " + kEscape + " 1", "Ns " + kEscape}) {
    folder.write("m.mtl", "newmtl a\n" + statement + "\n");
    const auto obj = folder.write("m.obj", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n");
    const ScopedLogCapture quiet;
    expect_escaped(testing::error_of([&] { load_obj(obj); }));
  }
}

}  // namespace
}  // namespace glint
