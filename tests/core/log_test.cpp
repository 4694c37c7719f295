#include "core/log.h"

#include <gtest/gtest.h>

namespace glint {
namespace {

TEST(ScopedLogCapture, RecordsWarningsInsteadOfPrintingAndRestoresOnExit) {
  {
    ScopedLogCapture capture;
    log_warning("dropped {} degenerate triangles", 3);
    log_info("loading {}", "x.obj");
    ASSERT_EQ(capture.entries().size(), 2u);
    EXPECT_EQ(capture.entries()[0].level, LogLevel::warning);
    EXPECT_EQ(capture.entries()[0].message, "dropped 3 degenerate triangles");
    EXPECT_EQ(capture.count_warnings("degenerate"), 1);
    EXPECT_EQ(capture.count_warnings("loading"), 0);  // info, not a warning
  }
  EXPECT_EQ(log_level(), LogLevel::warning);
}

TEST(ScopedLogCapture, NestsAndRoutesToTheInnermost) {
  ScopedLogCapture outer;
  {
    ScopedLogCapture inner;
    log_warning("inner");
    EXPECT_EQ(inner.entries().size(), 1u);
  }
  log_warning("outer");
  ASSERT_EQ(outer.entries().size(), 1u);
  EXPECT_EQ(outer.entries()[0].message, "outer");
}

}  // namespace
}  // namespace glint
