// The kd-tree in `glint bench`: --accels kdtree runs its cells (rebuild; refit skipped with the reason),
// Fig. 12 uses it when it comes first (as the paper did), and the report gains Fig. 11 (each
// structure's rebuild time against its render time) and Fig. 4 (the floor plan with the camera path),
// in summary.json, report.md and, with matplotlib, charts/fig11 and charts/fig4.
#include "app/bench/fig11_points.h"
#include "app/bench/paper_matrix.h"
#include "app/cli_runner.h"
#include "support/temp_folder.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace glint::testing {
namespace {

namespace fs = std::filesystem;

const nlohmann::json& cell_of(const nlohmann::json& summary, const std::string& id) {
  for (const nlohmann::json& cell : summary["cells"])
    if (cell["id"] == id) return cell;
  throw std::runtime_error("no cell " + id);
}

bool matplotlib_available() {
  return std::system("python3 -c 'import matplotlib' >/dev/null 2>&1") == 0 ||
         std::system("/usr/bin/python3 -c 'import matplotlib' >/dev/null 2>&1") == 0;
}

using BenchKdTree = GlTest;  // skips without headless OpenGL 4.5

TEST_F(BenchKdTree, QuickRunMeasuresTheKdTreeAndReportsFig11AndFig4) {
  TempFolder folder;
  const fs::path out = folder.path() / "bench";
  const CliResult r = run_glint("bench --experiment paper --quick --accels kdtree,sah --updates rebuild,refit --out " +
                                quoted(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json summary = nlohmann::json::parse(read_text_file(out / "summary.json"));
  for (const char* id : {"fig5-cpu-kdtree", "fig7-cpu-kdtree-rebuild", "fig10-cpu-kdtree-rebuild"})
    EXPECT_EQ(cell_of(summary, id)["status"], "done") << id;
  const nlohmann::json& refit = cell_of(summary, "fig7-cpu-kdtree-refit");
  EXPECT_EQ(refit["status"], "skipped");
  EXPECT_NE(refit["reason"].get<std::string>().find("kdtree cannot be refitted"), std::string::npos);
  // Fig. 12 takes the first structure, the kd-tree, as the paper's did; its deforming half rebuilds.
  EXPECT_EQ(cell_of(summary, "fig12-static-rt")["structure"], "cpu-kdtree");
  EXPECT_EQ(cell_of(summary, "fig12-deforming-rt")["status"], "done");
  EXPECT_EQ(cell_of(summary, "fig12-deforming-rt")["update"], "rebuild");

  ASSERT_EQ(summary["fig11"].size(), 2u) << summary["fig11"].dump();
  for (const nlohmann::json& point : summary["fig11"]) {
    EXPECT_GT(point["render_ms"].get<double>(), 0.0) << point.dump();
    EXPECT_GT(point["rebuild_ms"].get<double>(), 0.0) << point.dump();
    EXPECT_GT(point["build_ms"].get<double>(), 0.0) << point.dump();
  }
  EXPECT_EQ(summary["fig11"][0]["structure"], "cpu-kdtree");
  EXPECT_EQ(summary["fig11"][0]["rebuild_cell"], "fig7-cpu-kdtree-rebuild");

  const nlohmann::json& plan = summary["floor_plan"];
  EXPECT_EQ(plan["scene"], "atrium-simple");
  const nlohmann::json& grid = plan["grid"];
  ASSERT_EQ(grid["cells"].size(), grid["rows"].get<size_t>());
  std::string all;
  for (const nlohmann::json& row : grid["cells"]) {
    EXPECT_EQ(row.get<std::string>().size(), grid["columns"].get<size_t>());
    all += row.get<std::string>();
  }
  EXPECT_EQ(std::max(grid["rows"].get<int>(), grid["columns"].get<int>()), 200);
  EXPECT_NE(all.find('#'), std::string::npos) << "walls and columns stand at walking height";
  EXPECT_NE(all.find('d'), std::string::npos) << "the deforming creatures are marked";
  EXPECT_NE(all.find('.'), std::string::npos) << "the floor itself is left out";
  EXPECT_GT(plan["camera"].size(), 100u);
  EXPECT_EQ(plan["camera"].size(), plan["light"].size());
  ASSERT_EQ(plan["marked_frames"].size(), 4u);
  EXPECT_EQ(plan["marked_frames"][3]["frame"], 4400);

  const std::string report = read_text_file(out / "report.md");
  EXPECT_NE(report.find("## Fig. 4: floor plan of atrium-simple with the camera path"), std::string::npos);
  EXPECT_NE(report.find("| 2100 | "), std::string::npos);
  EXPECT_NE(report.find("### Fig. 11: rebuild time against render time per structure"), std::string::npos);
  EXPECT_NE(report.find("| cpu-kdtree | "), std::string::npos);
  EXPECT_LT(report.find("### Fig. 11"), report.find("### Fig. 12"));
  for (const char* chart : {"fig11", "fig4"}) {
    const bool made = fs::exists(out / "charts" / (std::string(chart) + ".png"));
    if (matplotlib_available()) {
      EXPECT_TRUE(made) << chart;
      EXPECT_TRUE(fs::exists(out / "charts" / (std::string(chart) + ".svg"))) << chart;
    }
    EXPECT_EQ(report.find("charts/" + std::string(chart) + ".png") != std::string::npos, made) << chart;
  }
}

TEST(BenchKdTreeMatrix, KdTreeCellsAreSkippedOnlyWhereTheyCannotRun) {
  bench::MatrixOptions options;
  options.structures = bench::structures_of({"cpu", "cuda", "gl"}, {"kdtree"});
  options.updates = {"refit", "rebuild"};
  for (const bench::Cell& cell : bench::paper_matrix(options)) {
    const bool refits = cell.update == "refit";
    const bool gl = cell.structure.backend == "gl" && !cell.reflections.empty() && cell.reflections != "ssr";
    const bool repeats = cell.figure == "fig8" || cell.figure == "fig9";
    if (repeats) continue;
    EXPECT_EQ(cell.skip_reason.has_value(), refits || gl) << cell.id;
  }
}

TEST(BenchFig11, PointsFallBackToTheSimplifiedSceneAndLeaveUnknownRebuildsNull) {
  const nlohmann::json cells = nlohmann::json::parse(R"([
    {"id": "fig8-cpu-lbvh", "figure": "fig8", "kind": "frame_times", "structure": "cpu-lbvh", "update": "",
     "status": "done", "frame_ms": {"mean": 12.5}, "ray_tracer": {"build_ms": 40.0}},
    {"id": "fig9-cpu-lbvh-rebuild", "figure": "fig9", "kind": "frame_times", "structure": "cpu-lbvh",
     "update": "rebuild", "status": "done", "frame_ms": {"mean": 60.0}, "mean_ms": {"accel_update": 7.5}},
    {"id": "fig5-embree", "figure": "fig5", "kind": "frame_times", "structure": "embree", "update": "",
     "status": "done", "frame_ms": {"mean": 9.0}},
    {"id": "fig7-embree-rebuild", "figure": "fig7", "kind": "frame_times", "structure": "embree",
     "update": "rebuild", "status": "failed"},
    {"id": "fig5-optix", "figure": "fig5", "kind": "frame_times", "structure": "optix", "update": "",
     "status": "skipped"},
    {"id": "fig12-static-rt", "figure": "fig12", "kind": "frame_times", "structure": "cpu-lbvh", "update": "",
     "status": "done", "frame_ms": {"mean": 99.0}}
  ])");
  const nlohmann::json points = bench::fig11_points(cells);
  ASSERT_EQ(points.size(), 2u) << points.dump();
  EXPECT_EQ(points[0]["structure"], "cpu-lbvh");
  EXPECT_EQ(points[0]["render_ms"], 12.5);
  EXPECT_EQ(points[0]["render_cell"], "fig8-cpu-lbvh");
  EXPECT_EQ(points[0]["rebuild_ms"], 7.5);
  EXPECT_EQ(points[0]["build_ms"], 40.0);
  EXPECT_EQ(points[1]["structure"], "embree");
  EXPECT_TRUE(points[1]["rebuild_ms"].is_null());
  EXPECT_TRUE(points[1]["rebuild_cell"].is_null());
  EXPECT_TRUE(points[1]["build_ms"].is_null());
}

}  // namespace
}  // namespace glint::testing
