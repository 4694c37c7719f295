// `glint render --backend optix` on the command line (any machine): optix structure names go with
// the optix backend only, and a machine or build that cannot run it is one line before anything is
// written.
#include "app/cli_runner.h"
#include "cuda/device_query.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <string>
#include <string_view>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

// Built by appending (GCC 12 warns falsely about "literal" + std::string under -O2).
std::string command(std::initializer_list<std::string_view> parts) {
  std::string text;
  for (const std::string_view part : parts) text += part;
  return text;
}
std::string quoted(const fs::path& path) { return command({"\"", path.string(), "\""}); }
long line_count(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(OptixCli, OptixStructuresGoWithTheOptixBackendOnly) {
  TempFolder folder;
  const fs::path out = folder.path() / "out";
  struct Case {
    const char* flags;
    const char* says;
  };
  for (const Case& c : {Case{"--backend cpu --accel optix-fastbuild", "needs --backend optix"},
                        Case{"--backend embree --accel optix-fasttrace", "needs --backend optix"},
                        Case{"--backend optix --accel lbvh", "the optix backend takes optix-fasttrace or optix-fastbuild"}}) {
    const CliResult r = run_glint(command({"render atrium-simple ", c.flags, " --out ", quoted(out)}));
    EXPECT_EQ(r.exit_code, 1) << c.flags;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << c.flags;
  }
  EXPECT_EQ(run_glint(command({"render atrium-simple --backend optix --accel optix-turbo --out ", quoted(out)})).exit_code,
            2);
}

TEST(OptixCli, OptixBackendWhereItCannotRunIsOneClearLine) {
  if (GLINT_HAVE_OPTIX && cuda_gpu_present()) GTEST_SKIP() << "this machine can run the optix backend";
  TempFolder folder;
  const fs::path out = folder.path() / "optix";
  for (const char* accel : {"optix-fasttrace", "optix-fastbuild", "sah"}) {
    const CliResult r = run_glint(command({"render atrium-simple --frames 2100 --width 32 --height 18 --backend optix --accel ",
                                           accel, " --out ", quoted(out)}));
    EXPECT_EQ(r.exit_code, 1) << accel;
    EXPECT_EQ(line_count(r.err), 1) << r.err;
    EXPECT_NE(r.err.find(GLINT_HAVE_OPTIX ? "CUDA GPU" : "built without OptiX"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(out)) << accel;
  }
}

}  // namespace
}  // namespace glint::testing
