// The command line's contract for bad input: one clear line on stderr, a non-zero exit, nothing on
// stdout.
#include "app/cli_runner.h"

#include <gtest/gtest.h>

namespace glint::testing {
namespace {

TEST(CliErrors, HelpListsTheSubcommandsAndExitsZero) {
  const CliResult r = run_glint("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("info"), std::string::npos);
}

TEST(CliErrors, UnknownFlagIsAUsageErrorWithExitCode2) {
  const CliResult r = run_glint("info atrium --no-such-flag");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--no-such-flag"), std::string::npos);
  EXPECT_TRUE(r.out.empty());
}

TEST(CliErrors, MissingSubcommandIsAUsageError) {
  const CliResult r = run_glint("");
  EXPECT_EQ(r.exit_code, 2);
}

TEST(CliErrors, MissingSceneFileIsOneLineNamingTheFile) {
  const CliResult r = run_glint("info /nonexistent/dir/model.obj");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("/nonexistent/dir/model.obj"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("no such file"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty());
}

TEST(CliErrors, UnknownSceneKindNamesThePresets) {
  const CliResult r = run_glint("info notes.txt");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("atrium"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(".scene.json"), std::string::npos) << r.err;
}

TEST(CliErrors, DirectoryInsteadOfAFileIsAnError) {
  const auto dir = std::filesystem::temp_directory_path() / "glint_cli_dir.obj";
  std::filesystem::create_directories(dir);
  const CliResult r = run_glint("info \"" + dir.string() + "\"");
  std::filesystem::remove_all(dir);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("is a directory"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace glint::testing
