// glint bench --time-limit (app/time_limit.h): the flag's values, and a run that stops at its limit
// with exit 75, keeps nothing half-done, writes no summary and is resumed by the same command.
#include "app/time_limit.h"

#include "app/cli_runner.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

namespace glint {
namespace {

namespace fs = std::filesystem;
using testing::CliResult;
using testing::quoted;
using testing::run_glint;
using testing::TempFolder;

TEST(TimeLimit, ReadsSecondsMinutesAndHours) {
  EXPECT_DOUBLE_EQ(parse_time_limit_seconds("--time-limit", "90"), 90.0);
  EXPECT_DOUBLE_EQ(parse_time_limit_seconds("--time-limit", "90s"), 90.0);
  EXPECT_DOUBLE_EQ(parse_time_limit_seconds("--time-limit", "50m"), 3000.0);
  EXPECT_DOUBLE_EQ(parse_time_limit_seconds("--time-limit", "1.5h"), 5400.0);
  EXPECT_DOUBLE_EQ(parse_time_limit_seconds("--time-limit", "0"), 0.0);
  for (const char* bad : {"", "m", "-1", "5d", "1h30m", "abc", "nan", "inf", " 5"}) {
    const std::string error = testing::error_of([&] { parse_time_limit_seconds("--time-limit", bad); });
    EXPECT_NE(error.find("--time-limit"), std::string::npos) << bad << ": " << error;
  }
}

TEST(TimeLimit, PassesWhenItsTimeHasGoneByAndNeverWithoutOne) {
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(TimeLimit::from_flag("--time-limit", "0", start).passed());
  EXPECT_FALSE(TimeLimit::from_flag("--time-limit", "1h", start).passed());
  EXPECT_TRUE(TimeLimit::from_flag("--time-limit", "1h", start - std::chrono::hours(2)).passed());
  EXPECT_FALSE(TimeLimit::from_flag("--time-limit", "", start).passed());
  EXPECT_FALSE(TimeLimit().until().has_value());
}

std::size_t cell_tables(const fs::path& out) {
  if (!fs::is_directory(out / "cells")) return 0;
  return static_cast<std::size_t>(std::count_if(fs::directory_iterator(out / "cells"), fs::directory_iterator(),
                                                [](const fs::directory_entry& e) { return e.path().extension() == ".csv"; }));
}

TEST(BenchTimeLimitCli, StopsWithExit75WithoutASummaryAndTheSameCommandResumes) {
  TempFolder folder;
  const fs::path out = folder.path() / "bench";
  const std::string command = "bench --experiment paper --quick --no-plot --out " + quoted(out);
  // A limit already passed at the first cell: nothing starts.
  const CliResult stopped = run_glint(command + " --time-limit 0");
  EXPECT_EQ(stopped.exit_code, kTimeLimitExitCode) << stopped.err;
  EXPECT_NE(stopped.err.find("time limit (0) has passed; 0 of"), std::string::npos) << stopped.err;
  EXPECT_NE(stopped.err.find("the same command resumes"), std::string::npos) << stopped.err;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  EXPECT_EQ(cell_tables(out), 0u);
  // Within its limit the run is an ordinary one, in the same folder.
  const CliResult finished = run_glint(command + " --time-limit 1h");
  ASSERT_EQ(finished.exit_code, 0) << finished.err;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
  EXPECT_GT(cell_tables(out), 0u);
}

TEST(BenchTimeLimitCli, BadValuesAndOtherExperimentsAreOneLine) {
  TempFolder folder;
  const fs::path out = folder.path() / "bench";
  const CliResult bad = run_glint("bench --experiment paper --quick --time-limit 5d --out " + quoted(out));
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_NE(bad.err.find("--time-limit"), std::string::npos) << bad.err;
  const CliResult adaptive = run_glint("bench --experiment adaptive --quick --time-limit 5m --out " + quoted(out));
  EXPECT_EQ(adaptive.exit_code, 1) << adaptive.err;
  EXPECT_NE(adaptive.err.find("--time-limit"), std::string::npos) << adaptive.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace glint
