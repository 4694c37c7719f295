#include "app/frame_selection.h"
#include "core/error.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace glint {
namespace {

using testing::error_of;
using Frames = std::vector<int>;

Frames resolve(const std::string& text, int frame_count = 4900) {
  return FrameSelection::parse(text).resolve(frame_count);
}

// The error message of parsing and resolving `text` against `frame_count` frames.
std::string error_for(const std::string& text, int frame_count = 4900) {
  return error_of([&] { FrameSelection::parse(text).resolve(frame_count); });
}

TEST(FrameSelection, SingleFrame) {
  EXPECT_EQ(resolve("0"), Frames{0});
  EXPECT_EQ(resolve("4899"), Frames{4899});
  EXPECT_EQ(resolve(" 42 "), Frames{42});
}

TEST(FrameSelection, InclusiveRange) {
  EXPECT_EQ(resolve("3:7"), (Frames{3, 4, 5, 6, 7}));
  EXPECT_EQ(resolve("5:5"), Frames{5});
  EXPECT_EQ(resolve("4895:4899"), (Frames{4895, 4896, 4897, 4898, 4899}));
}

TEST(FrameSelection, RangeWithStepStopsAtOrBeforeTheEnd) {
  EXPECT_EQ(resolve("0:10:5"), (Frames{0, 5, 10}));
  EXPECT_EQ(resolve("1:10:4"), (Frames{1, 5, 9}));
  EXPECT_EQ(resolve("2:3:100"), Frames{2});
  // 0:4905:7 would reach 4900, one past the end: only what the step actually selects counts.
  EXPECT_EQ(resolve("0:4899:7").back(), 4893);
  EXPECT_EQ(resolve("0:4899:7").size(), 700u);
}

TEST(FrameSelection, CommaListOfThePapersFrames) {
  EXPECT_EQ(resolve("1800,2100,2300,4400"), (Frames{1800, 2100, 2300, 4400}));
  EXPECT_EQ(resolve("1800, 2100 ,2300"), (Frames{1800, 2100, 2300}));
}

TEST(FrameSelection, MixedListIsSortedWithoutDuplicates) {
  EXPECT_EQ(resolve("0:10:5,100"), (Frames{0, 5, 10, 100}));
  EXPECT_EQ(resolve("100,0:4,2,3:6"), (Frames{0, 1, 2, 3, 4, 5, 6, 100}));
}

TEST(FrameSelection, AllSelectsEveryFrame) {
  const Frames frames = FrameSelection::all().resolve(5);
  EXPECT_EQ(frames, (Frames{0, 1, 2, 3, 4}));
  EXPECT_EQ(FrameSelection::all().text(), "all");
}

TEST(FrameSelection, KeepsItsText) { EXPECT_EQ(FrameSelection::parse("1,2:3").text(), "1,2:3"); }

TEST(FrameSelection, NegativeFrameIsAnError) {
  EXPECT_EQ(error_for("5,-3"), "frame selection \"5,-3\": \"-3\" is negative; frames count from 0");
  EXPECT_EQ(error_for("0:-2"), "frame selection \"0:-2\": \"-2\" is negative; frames count from 0");
  EXPECT_EQ(error_for("0:10:-1"), "frame selection \"0:10:-1\": \"-1\" is negative; frames count from 0");
}

TEST(FrameSelection, EndBeforeStartIsAnError) {
  EXPECT_EQ(error_for("1,10:5"), "frame selection \"1,10:5\": \"10:5\" ends at frame 5 before it starts at frame 10");
}

TEST(FrameSelection, StepZeroIsAnError) {
  EXPECT_EQ(error_for("0:10:0"), "frame selection \"0:10:0\": \"0:10:0\" has step 0; the step must be at least 1");
}

TEST(FrameSelection, FramePastTheEndIsAnError) {
  EXPECT_EQ(error_for("1800,5000"),
            "frame selection \"1800,5000\": frame 5000 is past the walkthrough's last frame 4899");
  EXPECT_EQ(error_for("4000:5000"),
            "frame selection \"4000:5000\": frame 5000 (in \"4000:5000\") is past the walkthrough's last frame 4899");
  EXPECT_EQ(error_for("0:4905:7"),
            "frame selection \"0:4905:7\": frame 4900 (in \"0:4905:7\") is past the walkthrough's last frame 4899");
  EXPECT_EQ(error_for("4900"), "frame selection \"4900\": frame 4900 is past the walkthrough's last frame 4899");
  // A huge range fails on its end, without first expanding two billion frames.
  EXPECT_NE(error_for("0:2000000000").find("frame 2000000000"), std::string::npos);
}

TEST(FrameSelection, WalkthroughWithoutFramesIsAnError) {
  EXPECT_EQ(error_for("0", 0), "frame selection \"0\": the walkthrough has no frames");
  EXPECT_EQ(error_of([] { FrameSelection::all().resolve(0); }), "frame selection \"all\": the walkthrough has no frames");
}

TEST(FrameSelection, GarbageIsAnErrorQuotingTheItem) {
  EXPECT_EQ(error_for("1,abc"),
            "frame selection \"1,abc\": \"abc\" is not a frame number (expected N, A:B or A:B:step)");
  EXPECT_EQ(error_for("12x"), "frame selection \"12x\": \"12x\" is not a frame number (expected N, A:B or A:B:step)");
  EXPECT_EQ(error_for("1.5"), "frame selection \"1.5\": \"1.5\" is not a frame number (expected N, A:B or A:B:step)");
  EXPECT_EQ(error_for("+3"), "frame selection \"+3\": \"+3\" is not a frame number (expected N, A:B or A:B:step)");
  EXPECT_EQ(error_for("0:1:2:3"),
            "frame selection \"0:1:2:3\": \"0:1:2:3\" has more than three parts (expected N, A:B or A:B:step)");
  EXPECT_EQ(error_for("5:"), "frame selection \"5:\": \"5:\" is missing a number");
  EXPECT_EQ(error_for("1,,2"), "frame selection \"1,,2\": empty item between commas");
  EXPECT_EQ(error_for("1,"), "frame selection \"1,\": empty item between commas");
  EXPECT_EQ(error_for(""), "frame selection \"\": no frames given");
  EXPECT_EQ(error_for("99999999999"), "frame selection \"99999999999\": \"99999999999\" is too large");
}

TEST(FrameSelection, SyntaxErrorsComeFromParseAlone) {
  EXPECT_THROW(FrameSelection::parse("7:3"), Error);
  EXPECT_THROW(FrameSelection::parse("x"), Error);
  EXPECT_NO_THROW(FrameSelection::parse("9999"));  // range is checked only against a walkthrough
}

}  // namespace
}  // namespace glint
