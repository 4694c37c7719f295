// OBJ files crafted to stall glint or to flood its messages: refused with "file:line:" errors whose
// quoted parts are bounded and escaped.
#include "core/error.h"
#include "core/log.h"
#include "scene/obj_loader.h"
#include "scene/obj_validation.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace glint {
namespace {

using testing::error_of;
using testing::TempFolder;

// One convex polygon of `vertices` vertices on the unit circle, as a single 'f' line (line n + 1).
std::string circle_face(std::size_t vertices) {
  std::string text;
  for (std::size_t i = 0; i < vertices; ++i) {
    const double angle = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(vertices);
    text += fmt::format("v {:.7f} {:.7f} 0\n", std::cos(angle), std::sin(angle));
  }
  text += "f";
  for (std::size_t i = 1; i <= vertices; ++i) text += fmt::format(" {}", i);
  return text + "\n";
}

TEST(ObjHostileInput, FacesAboveTheVertexLimitAreRefusedWithFileAndLine) {
  // A 200,000-vertex face held tinyobjloader's quadratic triangulation for minutes.
  TempFolder folder;
  const std::size_t too_many = kMaxObjFaceVertices + 1;
  const std::string message =
      error_of([&] { load_obj(folder.write("ngon.obj", circle_face(too_many))); });
  EXPECT_NE(message.find(fmt::format("ngon.obj:{}: the face has more than {} vertices", too_many + 1,
                                     kMaxObjFaceVertices)),
            std::string::npos)
      << message;
  // A face at the limit still loads, as kMaxObjFaceVertices - 2 triangles.
  ScopedLogCapture quiet;
  EXPECT_EQ(load_obj(folder.write("limit.obj", circle_face(kMaxObjFaceVertices))).triangle_count(),
            kMaxObjFaceVertices - 2);
}

TEST(ObjHostileInput, QuotedTokensAreBoundedAndEscaped) {
  TempFolder folder;
  const std::string huge(10'000'000, '7');
  const std::string message =
      error_of([&] { load_obj(folder.write("long.obj", "v 0 0 0\nv 1 0 0\nv 0 1 \x1b[2Jx" + huge + "\nf 1 2 3\n")); });
  EXPECT_NE(message.find("long.obj:3: 'v' line: '\\x1b[2Jx777"), std::string::npos) << message.substr(0, 400);
  EXPECT_NE(message.find("(10000005 bytes in all)"), std::string::npos) << message.substr(0, 400);
  EXPECT_LT(message.size(), 600u);
  EXPECT_EQ(message.find('\x1b'), std::string::npos);
}

}  // namespace
}  // namespace glint
