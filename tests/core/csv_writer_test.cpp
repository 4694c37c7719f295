#include "core/csv_writer.h"
#include "core/error.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace glint {
namespace {

namespace fs = std::filesystem;
using testing::error_of;
using testing::TempFolder;

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

bool folder_is_empty(const fs::path& folder) { return fs::directory_iterator(folder) == fs::directory_iterator(); }

TEST(CsvWriter, WritesExactText) {
  TempFolder folder;
  const fs::path path = folder.path() / "timings.csv";
  CsvWriter csv(path, {"frame", "mode", "total_ms", "rays"});
  csv.add_row({0, "hybrid", 15.25, std::int64_t{1234567890123}});
  csv.add_row({1, std::string("ssr"), 1.0 / 3.0, 0u});
  csv.add_row({2, std::string_view("rt"), 123456789.0, -7});
  EXPECT_EQ(csv.row_count(), 3u);
  csv.commit();
  EXPECT_EQ(read_text(path),
            "frame,mode,total_ms,rays\n"
            "0,hybrid,15.25,1234567890123\n"
            "1,ssr,0.333333,0\n"
            "2,rt,1.23457e+08,-7\n");
}

TEST(CsvWriter, FormatsNumbersWithSixSignificantDigitsAndIntegersExactly) {
  EXPECT_EQ(CsvField(0.1 + 0.2).text(), "0.3");  // no 0.30000000000000004 noise
  EXPECT_EQ(CsvField(2.0).text(), "2");
  EXPECT_EQ(CsvField(1e-7).text(), "1e-07");
  EXPECT_EQ(CsvField(2.5f).text(), "2.5");
  EXPECT_EQ(CsvField(std::numeric_limits<std::uint64_t>::max()).text(), "18446744073709551615");
  EXPECT_EQ(CsvField(std::numeric_limits<std::int64_t>::min()).text(), "-9223372036854775808");
  EXPECT_EQ(CsvField(std::nan("")).text(), "nan");
  EXPECT_EQ(CsvField(-std::numeric_limits<double>::infinity()).text(), "-inf");
}

TEST(CsvWriter, QuotesFieldsPerRfc4180) {
  EXPECT_EQ(csv_quote("plain text"), "plain text");
  EXPECT_EQ(csv_quote(""), "");
  EXPECT_EQ(csv_quote("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_quote("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_quote("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_quote("cr\r"), "\"cr\r\"");
  EXPECT_EQ(csv_quote("\""), "\"\"\"\"");

  TempFolder folder;
  const fs::path path = folder.path() / "quoted.csv";
  CsvWriter csv(path, {"scene", "note, with comma"});
  csv.add_row({"sponza \"v2\"", "a\nb"});
  csv.commit();
  EXPECT_EQ(read_text(path), "scene,\"note, with comma\"\n\"sponza \"\"v2\"\"\",\"a\nb\"\n");
}

TEST(CsvWriter, WrongColumnCountIsAnErrorAndWritesNothingOfTheRow) {
  TempFolder folder;
  const fs::path path = folder.path() / "t.csv";
  CsvWriter csv(path, {"a", "b", "c"});
  csv.add_row({1, 2, 3});
  const std::string too_few = error_of([&] { csv.add_row({4, 5}); });
  EXPECT_NE(too_few.find(path.string()), std::string::npos) << too_few;
  EXPECT_NE(too_few.find("row 2 has 2 fields, but the header has 3 columns"), std::string::npos) << too_few;
  const std::string too_many = error_of([&] { csv.add_row({4, 5, 6, 7}); });
  EXPECT_NE(too_many.find("row 2 has 4 fields"), std::string::npos) << too_many;
  csv.add_row({4, 5, 6});
  csv.commit();
  EXPECT_EQ(read_text(path), "a,b,c\n1,2,3\n4,5,6\n");
}

TEST(CsvWriter, BadHeadersAreErrors) {
  TempFolder folder;
  const fs::path path = folder.path() / "h.csv";
  EXPECT_NE(error_of([&] { CsvWriter csv(path, {}); }).find("at least one column"), std::string::npos);
  EXPECT_NE(error_of([&] { CsvWriter csv(path, {"a", ""}); }).find("column 2 has an empty name"), std::string::npos);
  EXPECT_NE(error_of([&] { CsvWriter csv(path, {"a", "b", "a"}); }).find("'a' appears twice"), std::string::npos);
  EXPECT_TRUE(folder_is_empty(folder.path()));
}

TEST(CsvWriter, NothingOnDiskUnderTheNameBeforeCommit) {
  TempFolder folder;
  const fs::path path = folder.path() / "big.csv";
  {
    CsvWriter csv(path, {"frame", "ms"});
    // Enough rows to overflow the write buffer: they are on disk in the temporary, not in memory...
    for (int frame = 0; frame < 20000; ++frame) csv.add_row({frame, frame * 0.5});
    EXPECT_FALSE(fs::exists(path));
    std::size_t temporary_bytes = 0;
    for (const auto& entry : fs::directory_iterator(folder.path())) temporary_bytes += entry.file_size();
    EXPECT_GT(temporary_bytes, 100'000u);
  }
  // ...and dropping the writer without commit leaves nothing at all.
  EXPECT_TRUE(folder_is_empty(folder.path()));
}

TEST(CsvWriter, CommitReplacesAnOlderTable) {
  TempFolder folder;
  const fs::path path = folder.write("t.csv", "old\n");
  CsvWriter csv(path, {"x"});
  csv.add_row({1});
  EXPECT_EQ(read_text(path), "old\n");
  csv.commit();
  EXPECT_EQ(read_text(path), "x\n1\n");
}

TEST(CsvWriter, MissingFolderIsAnErrorNamingThePath) {
  TempFolder folder;
  const fs::path path = folder.path() / "nope" / "t.csv";
  const std::string message = error_of([&] { CsvWriter csv(path, {"x"}); });
  EXPECT_NE(message.find(path.string()), std::string::npos) << message;
}

}  // namespace
}  // namespace glint
