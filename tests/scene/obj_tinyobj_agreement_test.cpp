// The OBJ loader's own validation pass and tinyobjloader must agree on which lines are vertices: where
// they do not, a face index the validation accepted would run past tinyobjloader's arrays.
#include "scene/obj_loader.h"

#include "core/error.h"
#include "core/log.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

TEST(ObjTinyobjAgreement, AVertexLineSeparatedByAVerticalTabIsAnErrorNotAnOverRead) {
  // To the validation pass "\v" is a blank, so the third line is a vertex; to tinyobjloader it is not,
  // and the face's index 3 has no vertex behind it (fuzz/regressions/obj_mtl/).
  testing::TempFolder folder;
  const auto obj = folder.write("tab.obj", std::string("v 0 0 0\nv 1 0 0\nv\v0 1 0\nf 1 2 3\n"));
  const ScopedLogCapture quiet;
  const std::string message = testing::error_of([&] { load_obj(obj); });
  EXPECT_NE(message.find("tab.obj: a face refers to an element that tinyobjloader did not read"), std::string::npos)
      << message;
  EXPECT_NE(message.find("2 v"), std::string::npos) << message;
}

TEST(ObjTinyobjAgreement, FormFeedSeparatedNormalsAreCaughtToo) {
  testing::TempFolder folder;
  const auto obj =
      folder.write("feed.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn\f0 0 1\nf 1//1 2//1 3//1\n"));
  const ScopedLogCapture quiet;
  EXPECT_NE(testing::error_of([&] { load_obj(obj); }).find("0 vn read"), std::string::npos);
}

}  // namespace
}  // namespace glint
