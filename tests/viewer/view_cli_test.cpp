// `glint view` as a person or a script runs it, on an X server of the test's own (Xvfb, Mesa's
// llvmpipe): a scripted session switching modes and backends writes its screenshots, a screenshot
// equals `glint render` of the same frame and settings, a bad script line is one error naming it
// and writes nothing, SIGINT and closing the window end it cleanly, and without a display it says so
// in one line (a script ending in quit runs offscreen instead). Small frames (320 x 180) and few of
// them keep this quick on two cores.
#include "app/cli_runner.h"
#include "core/image.h"
#include "metrics/rmse_psnr.h"
#include "support/scoped_env.h"
#include "support/temp_folder.h"
#include "viewer/virtual_display.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <thread>
#include <sys/wait.h>
#include <unistd.h>

#include "viewer/x11_window_closer.h"  // last: Xlib's macros

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSize = " --width 320 --height 180";

std::vector<std::string> hidden_files(const fs::path& folder) {
  std::vector<std::string> hidden;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.path().filename().string().starts_with(".")) hidden.push_back(entry.path().string());
  return hidden;
}

// `glint view atrium-simple` with `script` (written to the folder), run to its end.
CliResult view_script(const TempFolder& folder, const std::string& script, const std::string& flags = "") {
  const fs::path file = folder.write("session.txt", script);
  return run_glint("view atrium-simple" + kSize + flags + " --script " + quoted(file));
}

TEST(ViewCli, ScriptedSessionSwitchesModesAndBackendsAndWritesScreenshots) {
  const VirtualDisplay display;
  GLINT_REQUIRE_DISPLAY(display);
  const TempFolder folder;
  const fs::path shots = folder.path() / "shots";
  fs::create_directories(shots);
  const std::string s = shots.string() + "/";
  const CliResult result = view_script(folder, "frame 2100\n"
                                               "set reflections ssr\n"
                                               "screenshot " + s + "ssr.png\n"
                                               "set reflections hybrid\n"
                                               "set backend cpu\n"
                                               "screenshot " + s + "hybrid_cpu.png\n"
                                               "set backend embree\n"
                                               "set reflections rt\n"
                                               "set view difference\n"
                                               "screenshot " + s + "rt_embree.png\n"
                                               "set view final\n"
                                               "set backend gl\n"
                                               "screenshot " + s + "rt_gl.png\n"
                                               "camera 0,2,5 0,1,0\n"
                                               "set light stay\n"
                                               "screenshot " + s + "flown.png\n"
                                               "quit\n");
  ASSERT_EQ(result.exit_code, 0) << result.err;
  for (const char* name : {"ssr.png", "ssr_failure_mask.png", "ssr_ssr_reflection.png", "hybrid_cpu.png",
                           "hybrid_cpu_traced_reflection.png", "hybrid_cpu_albedo.png", "rt_embree.png",
                           "rt_embree_traced_reflection.png", "rt_embree_difference.png", "flown.png"})
    EXPECT_TRUE(fs::exists(shots / name)) << name;
  EXPECT_FALSE(fs::exists(shots / "rt_embree_failure_mask.png")) << "rt runs no SSR";
  EXPECT_TRUE(hidden_files(folder.path()).empty());
  const ImageRgba8 ssr = read_png(shots / "ssr.png"), rt = read_png(shots / "rt_embree.png");
  EXPECT_EQ(ssr.width, 320);
  EXPECT_EQ(ssr.height, 180);
  EXPECT_LT(metrics::rmse_psnr(ssr, rt).psnr, 60.0) << "switching the mode changed the picture";
  EXPECT_NE(read_png(shots / "flown.png").pixels, rt.pixels) << "the free camera sees another view";
  // The gl backend traces on the window's context (an EGL one, as it requires) and sees the same hits.
  EXPECT_GE(metrics::rmse_psnr(read_png(shots / "rt_gl.png"), rt).psnr, 50.0);
  // rt against its own reference: the heat map is black.
  const ImageRgba8 difference = read_png(shots / "rt_embree_difference.png");
  for (const glm::u8vec4& pixel : difference.pixels) ASSERT_EQ(pixel, glm::u8vec4(0, 0, 0, 255));
}

TEST(ViewCli, ScreenshotOfAFrameEqualsGlintRenderOfIt) {
  const VirtualDisplay display;
  GLINT_REQUIRE_DISPLAY(display);
  const TempFolder folder;
  const fs::path shot = folder.path() / "view.png";
  // Not the defaults everywhere: a setting given by flag and one set by the script.
  const CliResult viewed = view_script(folder, "set ssr-max-steps 64\nframe 2100\nscreenshot " + shot.string() + "\nquit\n",
                                       " --set backend=embree");
  ASSERT_EQ(viewed.exit_code, 0) << viewed.err;
  const CliResult rendered = run_glint("render atrium-simple" + kSize + " --backend embree --ssr-max-steps 64 --frames 2100 --out " +
                                       quoted(folder.path() / "render"));
  ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
  const double psnr =
      metrics::rmse_psnr(read_png(shot), read_png(folder.path() / "render" / "frame_02100.png")).psnr;
  EXPECT_GE(psnr, 50.0);
}

TEST(ViewCli, BadScriptLineIsOneErrorNamingItAndWritesNothing) {
  const VirtualDisplay display;
  GLINT_REQUIRE_DISPLAY(display);
  const TempFolder folder;
  const fs::path shot = folder.path() / "early.png";
  const CliResult result =
      view_script(folder, "frame 10\nscreenshot " + shot.string() + "\nset reflections sideways\nquit\n");
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("session.txt:3: reflections: \"sideways\" is not one of"), std::string::npos)
      << result.err;
  EXPECT_FALSE(fs::exists(shot)) << "the script is checked whole before its first line runs";
}

TEST(ViewCli, WithoutADisplayItSaysSoInOneLine) {
  const ScopedEnv no_display("DISPLAY", std::nullopt);
  const ScopedEnv no_wayland("WAYLAND_DISPLAY", std::nullopt);
  const CliResult result = run_glint("view atrium-simple" + kSize);
  EXPECT_EQ(result.exit_code, 1);
  EXPECT_EQ(line_count(result.err), 1) << result.err;
  EXPECT_NE(result.err.find("no display"), std::string::npos) << result.err;
  EXPECT_NE(result.err.find("xvfb-run"), std::string::npos) << result.err;
}

// Without a display a script that ends with `quit` runs offscreen (a headless EGL context, as
// `glint render`; how scripted sessions run on a headless GPU machine): its screenshot is `glint
// render`'s frame. A script without `quit` would leave a window open: it needs one and says so.
TEST(ViewCli, WithoutADisplayAScriptEndingInQuitRunsOffscreen) {
  const ScopedEnv no_display("DISPLAY", std::nullopt);
  const ScopedEnv no_wayland("WAYLAND_DISPLAY", std::nullopt);
  const TempFolder folder;
  const fs::path shot = folder.path() / "offscreen.png";
  const CliResult viewed =
      view_script(folder, "frame 2100\nscreenshot " + shot.string() + "\nquit\n", " --set backend=embree");
  ASSERT_EQ(viewed.exit_code, 0) << viewed.err;
  const CliResult rendered = run_glint("render atrium-simple" + kSize + " --backend embree --frames 2100 --out " +
                                       quoted(folder.path() / "render"));
  ASSERT_EQ(rendered.exit_code, 0) << rendered.err;
  EXPECT_GE(metrics::rmse_psnr(read_png(shot), read_png(folder.path() / "render" / "frame_02100.png")).psnr, 50.0);

  const CliResult left_open = view_script(folder, "frame 2100\n");
  EXPECT_EQ(left_open.exit_code, 1);
  EXPECT_EQ(line_count(left_open.err), 1) << left_open.err;
  EXPECT_NE(left_open.err.find("no display"), std::string::npos) << left_open.err;
}

TEST(ViewCli, OffscreenNeedsAScriptThatEndsWithQuit) {
  const CliResult no_script = run_glint("view atrium-simple --offscreen" + kSize);
  EXPECT_EQ(no_script.exit_code, 1);
  EXPECT_EQ(line_count(no_script.err), 1) << no_script.err;
  EXPECT_NE(no_script.err.find("--offscreen needs a --script"), std::string::npos) << no_script.err;
  const TempFolder folder;
  const CliResult no_quit = view_script(folder, "frame 10\n", " --offscreen");
  EXPECT_EQ(no_quit.exit_code, 1);
  EXPECT_NE(no_quit.err.find("session.txt: --offscreen runs the script to its end, which must be `quit`"),
            std::string::npos)
      << no_quit.err;
}

// Starts `glint view` with `script` in a child, waits until `ready()` (a minute at most), does
// `stop(child)` and returns the exit status (minus the signal that killed it).
template <typename Ready, typename Stop>
int view_until(const TempFolder& folder, const std::string& script, Ready ready, Stop stop) {
  const fs::path file = folder.write("session.txt", script);
  const pid_t child = ::fork();
  if (child == 0) {
    const std::string cli = cli_path();
    if (std::freopen("/dev/null", "w", stderr) == nullptr) ::_exit(126);
    ::execl(cli.c_str(), cli.c_str(), "view", "atrium-simple", "--width", "320", "--height", "180", "--script",
            file.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::minutes(1);
  while (!ready() && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  stop(child);
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

TEST(ViewCli, SigintEndsItCleanlyWithWholeFilesOnly) {
  const VirtualDisplay display;
  GLINT_REQUIRE_DISPLAY(display);
  const TempFolder folder;
  const fs::path shot = folder.path() / "first.png";
  const int status = view_until(
      folder, "screenshot " + shot.string() + "\nwait 600\n", [&] { return fs::exists(shot); },
      [](pid_t child) { ::kill(child, SIGINT); });
  EXPECT_EQ(status, 128 + SIGINT);
  EXPECT_TRUE(fs::exists(shot));
  EXPECT_TRUE(hidden_files(folder.path()).empty());
}

TEST(ViewCli, ClosingTheWindowEndsItWithStatusZero) {
  const VirtualDisplay display;
  GLINT_REQUIRE_DISPLAY(display);
  const TempFolder folder;
  const fs::path shot = folder.path() / "first.png";
  bool closed = false;
  const int status = view_until(
      folder, "screenshot " + shot.string() + "\nwait 600\n", [&] { return fs::exists(shot); },
      [&](pid_t child) {
        closed = close_x11_window("glint view: atrium-simple");
        if (!closed) ::kill(child, SIGKILL);
      });
  ASSERT_TRUE(closed) << "no window titled \"glint view: atrium-simple\" on " << display.display();
  EXPECT_EQ(status, 0);
  EXPECT_TRUE(hidden_files(folder.path()).empty());
}

}  // namespace
}  // namespace glint::testing
