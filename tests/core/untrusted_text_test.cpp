#include "core/untrusted_text.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

TEST(UntrustedText, KeepsPlainTextAndUtf8) {
  EXPECT_EQ(untrusted_text("sponza/floor_01.png"), "sponza/floor_01.png");
  EXPECT_EQ(untrusted_text("caf\xc3\xa9 \xe2\x82\xac"), "caf\xc3\xa9 \xe2\x82\xac");
}

TEST(UntrustedText, EscapesControlCharactersBackslashesAndInvalidUtf8) {
  EXPECT_EQ(untrusted_text("a\nb\tc\rd"), "a\\nb\\tc\\rd");
  EXPECT_EQ(untrusted_text(std::string("\x1b[2J\x07\x7f", 6)), "\\x1b[2J\\x07\\x7f");
  EXPECT_EQ(untrusted_text(std::string("nul\0end", 7)), "nul\\x00end");
  EXPECT_EQ(untrusted_text("back\\slash"), "back\\\\slash");
  EXPECT_EQ(untrusted_text("\xc2\x9b" "31m"), "\\u009b31m");  // C1 CSI, which some terminals obey
  EXPECT_EQ(untrusted_text("\xff\xc3"), "\\xff\\xc3");        // not UTF-8 (a truncated sequence too)
  EXPECT_EQ(untrusted_text("\xc0\xaf"), "\\xc0\\xaf");        // overlong '/'
}

TEST(UntrustedText, TruncatesLongTextAndSaysHowLongItWas) {
  const std::string huge(50'000'000, 'x');
  const std::string shown = untrusted_text(huge);
  EXPECT_LT(shown.size(), kUntrustedTextMaxBytes + 40);
  EXPECT_EQ(shown.substr(0, 10), "xxxxxxxxxx");
  EXPECT_NE(shown.find("... (50000000 bytes in all)"), std::string::npos) << shown;
  // A multi-byte character is never cut in half.
  std::string euros;
  for (int i = 0; i < 200; ++i) euros += "\xe2\x82\xac";
  const std::string cut = untrusted_text(euros);
  const std::string kept = cut.substr(0, cut.find("..."));
  EXPECT_EQ(kept.size() % 3, 0u);
  EXPECT_LE(kept.size(), kUntrustedTextMaxBytes);
}

}  // namespace
}  // namespace glint
