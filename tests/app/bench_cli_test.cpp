// `glint bench` as a user runs it: `--quick` produces every promised file, well-formed, a second run
// resumes (renders nothing, writes the same summary), a damaged cell is measured again, and bad
// input is one line that writes nothing. The quick run is the only bench test that renders.
#include "app/cli_runner.h"
#include "core/image.h"
#include "cuda/device_query.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

using BenchCli = GlTest;  // skips without headless OpenGL 4.5 (the command would fail)

std::size_t column(const std::vector<std::string>& header, const std::string& name) {
  const auto found = std::find(header.begin(), header.end(), name);
  EXPECT_NE(found, header.end()) << name;
  return static_cast<std::size_t>(found - header.begin());
}

// As glint looks for it: PATH's python3, else Debian's.
bool matplotlib_available() {
  return std::system("python3 -c 'import matplotlib' >/dev/null 2>&1") == 0 ||
         std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

const nlohmann::json& cell_named(const nlohmann::json& summary, const std::string& id) {
  for (const nlohmann::json& cell : summary["cells"])
    if (cell["id"] == id) return cell;
  ADD_FAILURE() << "no cell " << id << " in summary.json";
  static const nlohmann::json none;
  return none;
}

// The checks of a frame-times cell's CSV and summary entry.
void check_frame_times_cell(const fs::path& out, const nlohmann::json& cell) {
  SCOPED_TRACE(cell["id"].get<std::string>());
  const auto csv = read_csv(out / cell["csv"].get<std::string>());
  ASSERT_EQ(csv.size(), 5u) << "header + frames 0, 1225, 2450, 3675";
  const std::vector<std::string>& header = csv[0];
  ASSERT_EQ(header.size(), 29u);
  EXPECT_EQ(header[0], "frame");
  const std::vector<std::string> frames = {"0", "1225", "2450", "3675"};
  for (std::size_t row = 1; row < csv.size(); ++row) {
    ASSERT_EQ(csv[row].size(), header.size());
    EXPECT_EQ(csv[row][0], frames[row - 1]);
    EXPECT_GT(std::stod(csv[row][column(header, "frame_ms")]), 0.0);
    EXPECT_GT(std::stod(csv[row][column(header, "frame_latency_ms")]), 0.0);
    const std::string mode = cell["reflections"];
    const std::string& rays = csv[row][column(header, "rays_traced")];
    const std::string& reflective = csv[row][column(header, "reflective_pixels")];
    const std::string& failed = csv[row][column(header, "ssr_failed_pixels")];
    if (mode == "ssr") {
      EXPECT_EQ(rays, "") << "ssr traces no rays";
    } else if (mode == "hybrid") {
      EXPECT_EQ(rays, failed) << "hybrid traces exactly SSR's failed pixels";
    } else {
      EXPECT_EQ(rays, reflective) << "rt traces every reflective pixel";
    }
  }
  EXPECT_EQ(cell["frames"], 4);
  const nlohmann::json& ms = cell["frame_ms"];
  EXPECT_LE(ms["min"].get<double>(), ms["p5"].get<double>());
  EXPECT_LE(ms["p5"].get<double>(), ms["median"].get<double>());
  EXPECT_LE(ms["median"].get<double>(), ms["p95"].get<double>());
  EXPECT_LE(ms["p95"].get<double>(), ms["max"].get<double>());
  ASSERT_EQ(cell["intervals"].size(), 2u) << "4 measured frames in intervals of 2";
  EXPECT_EQ(cell["intervals"][0]["first_frame"], 0);
  EXPECT_EQ(cell["intervals"][1]["last_frame"], 3675);
  const double interval_mean =
      (cell["intervals"][0]["mean_ms"].get<double>() + cell["intervals"][1]["mean_ms"].get<double>()) / 2.0;
  EXPECT_NEAR(interval_mean, ms["mean"].get<double>(), 1e-6 * ms["mean"].get<double>());
}

void check_quality_cell(const fs::path& out, const nlohmann::json& cell) {
  SCOPED_TRACE(cell["id"].get<std::string>());
  const auto csv = read_csv(out / cell["csv"].get<std::string>());
  ASSERT_EQ(csv.size(), 9u) << "header + 4 frames x (ssr, hybrid)";
  const std::vector<std::string> header = {"frame",        "mode", "buckets_r_percent", "buckets_g_percent",
                                           "buckets_b_percent", "buckets_mean_percent", "ssim_luma", "rmse", "psnr_db"};
  EXPECT_EQ(csv[0], header);
  for (std::size_t row = 1; row < csv.size(); ++row) {
    ASSERT_EQ(csv[row].size(), header.size());
    EXPECT_EQ(csv[row][1], row % 2 == 1 ? "ssr" : "hybrid");
    for (std::size_t c = 2; c <= 5; ++c) {
      EXPECT_GE(std::stod(csv[row][c]), 0.0);
      EXPECT_LE(std::stod(csv[row][c]), 100.0);
    }
    EXPECT_LE(std::stod(csv[row][6]), 1.0);
    EXPECT_GE(std::stod(csv[row][7]), 0.0);
  }
  for (const char* frame : {"01800", "02100", "02300", "04400"})
    for (const char* mode : {"rt", "ssr", "hybrid"}) {
      const fs::path image = out / cell["images"].get<std::string>() / (std::string("frame_") + frame + "_" + mode + ".png");
      ASSERT_TRUE(fs::exists(image)) << image;
      const ImageRgba8 png = read_png(image);
      EXPECT_EQ(png.width, 96);
      EXPECT_EQ(png.height, 54);
    }
}

std::map<fs::path, fs::file_time_type> cell_csv_times(const fs::path& out) {
  std::map<fs::path, fs::file_time_type> times;
  for (const auto& entry : fs::directory_iterator(out / "cells"))
    if (entry.path().extension() == ".csv") times[entry.path()] = entry.last_write_time();
  return times;
}

TEST_F(BenchCli, QuickRunWritesEveryOutputResumesAndRemeasuresADamagedCell) {
  TempFolder folder;
  const fs::path out = folder.path() / "bench";
  const std::string command = "bench --experiment paper --quick --backends cpu,cuda --out " + quoted(out);
  const CliResult first = run_glint(command);
  ASSERT_EQ(first.exit_code, 0) << first.err;

  const std::string summary_text = read_text_file(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(summary_text);
  EXPECT_EQ(summary["experiment"], "paper");
  EXPECT_NE(summary["command"].get<std::string>().find("--quick"), std::string::npos);
  EXPECT_FALSE(summary["environment"]["gl"]["renderer"].get<std::string>().empty());
  EXPECT_FALSE(summary["environment"]["glint_version"].get<std::string>().empty());
  EXPECT_TRUE(summary["environment"].contains("git_commit"));
  EXPECT_EQ(summary["settings"]["width"], 96);
  EXPECT_EQ(summary["settings"]["height"], 54);
  EXPECT_EQ(summary["settings"]["stride"], 1225);
  ASSERT_EQ(summary["backends"].size(), 2u);
  EXPECT_EQ(summary["backends"][0]["name"], "cpu");
  EXPECT_EQ(summary["backends"][0]["available"], true);
  EXPECT_EQ(summary["backends"][1]["name"], "cuda");
  if (!cuda_gpu_present()) {
    EXPECT_EQ(summary["backends"][1]["available"], false);
    EXPECT_FALSE(summary["backends"][1]["reason"].get<std::string>().empty());
  }

  // Every figure and table has its cells; none is silently missing, none failed.
  std::set<std::string> figures;
  for (const nlohmann::json& cell : summary["cells"]) {
    figures.insert(cell["figure"].get<std::string>());
    const std::string status = cell["status"];
    EXPECT_NE(status, "failed") << cell["id"] << ": " << cell.value("reason", "");
    if (status == "skipped") {
      EXPECT_FALSE(cell["reason"].get<std::string>().empty()) << cell["id"];
      continue;
    }
    if (cell["kind"] == "quality") check_quality_cell(out, cell);
    else check_frame_times_cell(out, cell);
  }
  EXPECT_EQ(figures, (std::set<std::string>{"fig5", "fig7", "fig8", "fig9", "fig10", "fig12", "table1", "table2"}));
  for (const char* id : {"fig5-cpu-sah", "fig7-cpu-sah-refit", "fig10-cpu-sah-refit", "fig12-static-ssr",
                         "fig12-static-hybrid", "fig12-static-rt", "fig12-deforming-ssr", "fig12-deforming-hybrid",
                         "fig12-deforming-rt", "table1-static", "table2-deforming"})
    EXPECT_EQ(cell_named(summary, id)["status"], "done") << id;
  EXPECT_NE(cell_named(summary, "fig8-cpu-sah")["reason"].get<std::string>().find("same scene"), std::string::npos)
      << "--quick uses atrium-simple for both scenes, so Fig. 8 would repeat Fig. 5";
  if (!cuda_gpu_present()) {
    const nlohmann::json& cuda = cell_named(summary, "fig5-cuda-sah");
    EXPECT_EQ(cuda["status"], "skipped");
    EXPECT_NE(cuda["reason"].get<std::string>().find("cuda"), std::string::npos) << cuda["reason"];
  }
  EXPECT_GT(cell_named(summary, "fig10-cpu-sah-refit")["ray_tracer"]["refits"].get<int>(), 0);

  const std::string report = read_text_file(out / "report.md");
  for (const char* section : {"# glint bench", "## Setup", "## Cells", "## Frame times", "### Fig. 5", "### Fig. 12",
                              "## Image quality", "### Table I:", "### Table II:", "## Skipped and failed cells",
                              "## Charts", "| Resolution | 96x54 |", "| GL renderer |", "| Commit |", "--stride",
                              "fig8-cpu-sah", "| Shadows | cube: cube map 128x128 per face |", "| G-buffer | raster |",
                              "| Frame time | steady state"})
    EXPECT_NE(report.find(section), std::string::npos) << section;
  EXPECT_NE(report.find(summary["command"].get<std::string>()), std::string::npos) << "the command line";
  EXPECT_TRUE(fs::exists(out / "plot_bench.py"));
  if (matplotlib_available()) {
    for (const char* chart : {"fig5", "fig7", "fig10", "fig12", "table1", "table2"})
      for (const char* extension : {".png", ".svg"})
        EXPECT_GT(fs::file_size(out / "charts" / (std::string(chart) + extension)), 0u) << chart << extension;
    EXPECT_NE(report.find("](charts/fig5.png)"), std::string::npos);
  } else {
    EXPECT_NE(first.err.find("plot_bench.py"), std::string::npos) << "a warning says how to plot by hand";
  }
  EXPECT_NE(first.out.find("fig5-cpu-sah"), std::string::npos) << "the final table names the cells";
  for (const auto& entry : fs::recursive_directory_iterator(out))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary left behind: " << entry.path();

  // The same command again keeps every finished cell: nothing is rendered, the summary is the same.
  const auto csv_times = cell_csv_times(out);
  const CliResult second = run_glint(command);
  ASSERT_EQ(second.exit_code, 0) << second.err;
  EXPECT_EQ(read_text_file(out / "summary.json"), summary_text);
  EXPECT_EQ(cell_csv_times(out), csv_times) << "no cell was measured again";
  EXPECT_NE(second.out.find("kept from an earlier run"), std::string::npos) << second.out;

  // A cell whose CSV lost a row (an edited or damaged file) is measured again, and only that one.
  const fs::path damaged = out / "cells" / "fig5-cpu-sah.csv";
  const auto rows = read_csv(damaged);
  {
    std::ofstream file(damaged, std::ios::trunc);
    for (std::size_t r = 0; r + 1 < rows.size(); ++r) {
      for (std::size_t f = 0; f < rows[r].size(); ++f) file << (f ? "," : "") << rows[r][f];
      file << "\n";
    }
  }
  const auto before_third = cell_csv_times(out);
  const CliResult third = run_glint(command);
  ASSERT_EQ(third.exit_code, 0) << third.err;
  EXPECT_NE(third.err.find("fig5-cpu-sah.csv"), std::string::npos) << "a warning names the damaged cell";
  EXPECT_EQ(read_csv(damaged).size(), 5u) << "the cell is whole again";
  for (const auto& [path, time] : cell_csv_times(out))
    if (path != damaged) {
      EXPECT_EQ(time, before_third.at(path)) << path;
    }
}

TEST(BenchCliErrors, BadFlagsAndUnknownExperimentAreOneLineAndWriteNothing) {
  TempFolder folder;
  const fs::path out = folder.path() / "bench";
  for (const char* flags : {"--experiment figure5", "--experiment paper --backends cpu,vulkan",
                            "--experiment paper --accels sah,octree", "--experiment paper --updates sometimes",
                            "--experiment paper --backends cpu,cpu", "--experiment paper --accels ,",
                            "--experiment paper --scene /nonexistent/scene.obj"}) {
    const CliResult r = run_glint(std::string("bench ") + flags + " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 1) << flags;
    EXPECT_EQ(line_count(r.err), 1) << flags << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << flags;
    EXPECT_FALSE(fs::exists(out)) << flags;
  }
  const CliResult experiment = run_glint("bench --experiment figure5 --out " + quoted(out));
  EXPECT_NE(experiment.err.find("figure5"), std::string::npos) << experiment.err;
  EXPECT_NE(experiment.err.find("paper"), std::string::npos) << "names the known experiments: " << experiment.err;
  const CliResult backend = run_glint("bench --experiment paper --backends cpu,vulkan --out " + quoted(out));
  EXPECT_NE(backend.err.find("vulkan"), std::string::npos) << backend.err;

  // Flags CLI11 rejects are usage errors (exit 2), their first line naming the flag.
  for (const char* flags : {"--experiment paper --stride 0", "--experiment paper --width 0", "--experiment paper",
                            "--quick", "--experiment paper --frames -3"}) {
    const std::string out_flag = std::string(flags) == "--experiment paper" ? "" : " --out " + quoted(out);
    const CliResult r = run_glint(std::string("bench ") + flags + out_flag);
    EXPECT_EQ(r.exit_code, 2) << flags;
    EXPECT_FALSE(fs::exists(out)) << flags;
  }
  EXPECT_NE(run_glint("bench --experiment paper --stride 0 --out " + quoted(out)).err.find("--stride"), std::string::npos);
}

TEST(BenchCliErrors, AFolderHoldingARunWithOtherSettingsIsNotMixedWithThisOne) {
  TempFolder folder;
  const fs::path settings = folder.write("bench/bench_settings.json", R"({"experiment": "paper", "width": 640})");
  const CliResult r = run_glint("bench --experiment paper --quick --out " + quoted(folder.path() / "bench"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("bench_settings.json"), std::string::npos) << r.err;
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::recursive_directory_iterator(folder.path() / "bench")) ++files;
  EXPECT_EQ(files, 1u) << "nothing but the earlier run's settings";
}

}  // namespace
}  // namespace glint::testing
