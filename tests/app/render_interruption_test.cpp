// `glint render` stopped by SIGINT or SIGTERM keeps what it finished (frames, their timings.csv rows,
// run.json marked as interrupted), leaves no temporaries and exits with 128 + the signal; and an
// output folder that holds an earlier run is refused unless --overwrite.
#include "app/cli_runner.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <csignal>
#include <filesystem>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> files_in(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(folder)) files.push_back(entry.path().filename());
  std::sort(files.begin(), files.end());
  return files;
}

int count_frames(const fs::path& folder) {
  int frames = 0;
  for (const fs::path& name : files_in(folder))
    frames += name.string().starts_with("frame_") && name.extension() == ".png";
  return frames;
}

// Starts `glint <arguments>` in a child process, waits until `ready()` (or three minutes), sends
// `signal` and returns the exit status (or minus the signal that ended it).
template <typename Ready>
int run_and_signal(const std::vector<std::string>& arguments, Ready ready, int signal) {
  const pid_t child = ::fork();
  if (child == 0) {
    const std::string cli = cli_path();
    std::vector<char*> argv{const_cast<char*>(cli.c_str())};
    for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
    argv.push_back(nullptr);
    // Quiet: stderr would mix into the test log.
    if (std::freopen("/dev/null", "w", stderr) == nullptr) ::_exit(126);
    ::execv(cli.c_str(), argv.data());
    ::_exit(127);
  }
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(3);
  while (!ready() && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ::kill(child, signal);
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

// `glint render` of 401 small frames, signalled once its first frame is written.
int render_and_signal(const fs::path& out, int signal) {
  return run_and_signal({"render", "atrium-simple", "--reflections", "rt", "--backend", "embree", "--width", "32",
                         "--height", "18", "--frames", "0:400", "--out", out.string()},
                        [&] { return fs::exists(out) && count_frames(out) > 0; }, signal);
}

void expect_whole_partial_run(const fs::path& out, const char* signal_name) {
  const int frames = count_frames(out);
  EXPECT_GE(frames, 1);
  EXPECT_LT(frames, 401) << "the run stopped early";
  for (const fs::path& name : files_in(out)) EXPECT_FALSE(name.string().starts_with(".")) << "temporary left: " << name;
  const auto csv = read_csv(out / "timings.csv");
  EXPECT_EQ(static_cast<int>(csv.size()), frames + 1) << "one row per frame written, and the header";
  for (std::size_t row = 1; row < csv.size(); ++row) EXPECT_EQ(csv[row][0], std::to_string(row - 1));
  const auto run = nlohmann::json::parse(read_text_file(out / "run.json"));
  EXPECT_EQ(run["interrupted_by"], signal_name);
  EXPECT_EQ(run["frames_rendered"], frames);
}

TEST(RenderInterruption, SigintKeepsTheFinishedFramesTheirTimingsAndRunRecord) {
  const TempFolder temp;
  const fs::path out = temp.path() / "out";
  EXPECT_EQ(render_and_signal(out, SIGINT), 128 + SIGINT);
  expect_whole_partial_run(out, "SIGINT");
}

TEST(RenderInterruption, SigtermToo) {
  const TempFolder temp;
  const fs::path out = temp.path() / "out";
  EXPECT_EQ(render_and_signal(out, SIGTERM), 128 + SIGTERM);
  expect_whole_partial_run(out, "SIGTERM");
}

// A quick paper bench stopped once its first cell is done: the finished cell stays, no temporary is
// left anywhere, and the same command then resumes (keeps that cell) and completes.
TEST(BenchInterruption, StopsTheCellUnderWayKeepsFinishedCellsAndResumes) {
  const TempFolder temp;
  const fs::path out = temp.path() / "bench";
  const std::vector<std::string> arguments{"bench", "--experiment", "paper", "--quick", "--backends", "cpu",
                                           "--no-plot", "--out", out.string()};
  const auto cells_done = [&] {
    std::error_code ignored;
    if (!fs::is_directory(out / "cells", ignored)) return 0;
    int done = 0;
    for (const auto& entry : fs::directory_iterator(out / "cells", ignored))
      done += entry.path().extension() == ".csv" && !entry.path().filename().string().starts_with(".");
    return done;
  };
  EXPECT_EQ(run_and_signal(arguments, [&] { return cells_done() > 0; }, SIGINT), 128 + SIGINT);
  const int kept = cells_done();
  EXPECT_GE(kept, 1);
  for (const auto& entry : fs::recursive_directory_iterator(out))
    EXPECT_FALSE(entry.path().filename().string().starts_with(".")) << "temporary left: " << entry.path();
  EXPECT_FALSE(fs::exists(out / "summary.json")) << "an interrupted run writes no summary of cells it did not run";

  std::string command = "bench --experiment paper --quick --backends cpu --no-plot --out " + quoted(out);
  const CliResult resumed = run_glint(command);
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("kept from an earlier run"), std::string::npos) << resumed.out;
  EXPECT_TRUE(fs::exists(out / "summary.json"));
}

TEST(RenderOutputFolder, AnEarlierRunIsRefusedUnlessOverwrite) {
  const TempFolder temp;
  const fs::path out = temp.path() / "out";
  const std::string args = "render atrium-simple --reflections off --out " + quoted(out);
  ASSERT_EQ(run_glint(args + " --width 32 --height 18 --frames 7,8").exit_code, 0);
  ASSERT_TRUE(fs::exists(out / "frame_00008.png"));

  const CliResult refused = run_glint(args + " --width 16 --height 9 --frames 5");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_EQ(line_count(refused.err), 1) << refused.err;
  EXPECT_NE(refused.err.find("holds an earlier run"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--overwrite"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(out / "frame_00005.png"));

  fs::create_directories(out / "notes");
  std::ofstream(out / "notes.txt") << "mine";
  const CliResult replaced = run_glint(args + " --width 16 --height 9 --frames 5 --overwrite");
  ASSERT_EQ(replaced.exit_code, 0) << replaced.err;
  EXPECT_EQ(files_in(out), (std::vector<fs::path>{"frame_00005.png", "notes", "notes.txt", "run.json", "timings.csv"}))
      << "the earlier run's frames are gone, the user's own files stay";
}

TEST(RenderOutputFolder, AFolderThatCannotBeWrittenIsOneClearLine) {
  const std::string args = "render atrium-simple --reflections off --width 8 --height 8 --frames 0 --out ";
  const CliResult proc = run_glint(args + "/proc/self");
  EXPECT_EQ(proc.exit_code, 1);
  EXPECT_EQ(line_count(proc.err), 1) << proc.err;
  EXPECT_NE(proc.err.find("output folder '/proc/self' is not writable"), std::string::npos) << proc.err;

  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders";
  const TempFolder temp;
  const fs::path locked = temp.path() / "locked";
  fs::create_directories(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const CliResult r = run_glint(args + quoted(locked));
  fs::permissions(locked, fs::perms::owner_all);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("is not writable"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace glint::testing
