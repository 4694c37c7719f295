// glint bench's resume bookkeeping: which cell tables count as finished, and refusing to mix runs
// with different settings in one folder.
#include "app/bench/resume.h"

#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

namespace glint::bench {
namespace {

const std::vector<std::string> kHeader = {"frame", "mode", "ms", "psnr"};

CsvTable table(std::vector<std::vector<std::string>> rows) { return {kHeader, std::move(rows)}; }

TEST(BenchResume, AFinishedTableHasTheHeaderTheRowsInOrderAndNumbers) {
  const std::vector<RowKey> keys = {{"0", "ssr"}, {"0", "hybrid"}, {"10", "ssr"}, {"10", "hybrid"}};
  const CsvTable good = table({{"0", "ssr", "1.5", "inf"}, {"0", "hybrid", "2", "31.2"}, {"10", "ssr", "", "40"},
                               {"10", "hybrid", "3e-1", "nan"}});
  EXPECT_EQ(finished_cell_problem(good, kHeader, keys), std::nullopt);

  CsvTable other_header = good;
  other_header.header[2] = "seconds";
  EXPECT_NE(finished_cell_problem(other_header, kHeader, keys)->find("header"), std::string::npos);
  CsvTable short_table = good;
  short_table.rows.pop_back();
  EXPECT_EQ(*finished_cell_problem(short_table, kHeader, keys), "3 rows, expected 4");
  CsvTable swapped = good;
  std::swap(swapped.rows[0], swapped.rows[1]);
  EXPECT_NE(finished_cell_problem(swapped, kHeader, keys)->find("row 1 starts with hybrid"), std::string::npos);
  CsvTable cut = good;
  cut.rows[2].pop_back();
  EXPECT_NE(finished_cell_problem(cut, kHeader, keys)->find("row 3 has 3 fields"), std::string::npos);
  CsvTable garbage = good;
  garbage.rows[3][2] = "12ms";
  EXPECT_NE(finished_cell_problem(garbage, kHeader, keys)->find("'12ms' is not a number"), std::string::npos);
}

TEST(BenchResume, ReadsTablesAndReportsMissingFiles) {
  testing::TempFolder folder;
  const auto path = folder.write("cell.csv", "frame,mode,ms,psnr\n0,ssr,1.5,inf\n0,hybrid,,2\n");
  const std::optional<CsvTable> read = read_csv_table(path);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->header, kHeader);
  ASSERT_EQ(read->rows.size(), 2u);
  EXPECT_EQ(read->rows[1], (std::vector<std::string>{"0", "hybrid", "", "2"})) << "an empty field is kept";
  EXPECT_FALSE(read_csv_table(folder.path() / "missing.csv"));
}

TEST(BenchResume, RunSettingsMustMatchTheFoldersEarlierRun) {
  testing::TempFolder folder;
  const nlohmann::json settings = {{"width", 96}, {"scene", "atrium-simple"}};
  check_run_settings(folder.path(), settings);  // no earlier run: nothing to check
  write_run_settings(folder.path(), settings);
  check_run_settings(folder.path(), settings);
  nlohmann::json wider = settings;
  wider["width"] = 128;
  const std::string error = testing::error_of([&] { check_run_settings(folder.path(), wider); });
  EXPECT_NE(error.find("width 96, this run has 128"), std::string::npos) << error;
  folder.write("bench_settings.json", "not json");
  EXPECT_NE(testing::error_of([&] { check_run_settings(folder.path(), settings); }).find("not a JSON object"),
            std::string::npos);
}

}  // namespace
}  // namespace glint::bench
