#include "app/bench/bench_report.h"

#include "app/mpi/bench_share.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <vector>

namespace glint::bench {
namespace {

struct FigureText {
  const char* figure;
  const char* title;
  const char* paper;  // the paper's numbers (GTX 780 Ti, OptiX 3/4, 1280x720, 4900 frames)
};

constexpr FigureText kFigures[] = {
    {"fig5", "Fig. 5: static full scene, frame time per structure (hybrid)",
     "Paper: Lbvh 16.0 ms, Bvh 15.6, MedianBvh 15.8, KD-tree 15.3."},
    {"fig7", "Fig. 7: full scene, both dinosaurs deforming every frame (hybrid)",
     "Paper (rebuild every frame): Lbvh 85.4 ms, Bvh 163.0, MedianBvh 94.7, KD-tree 159.1."},
    {"fig8", "Fig. 8: simplified scene, static (hybrid)",
     "Paper: Lbvh 13.2 ms, Bvh 12.4, MedianBvh 12.7, KD-tree 12.3."},
    {"fig9", "Fig. 9: simplified scene, both dinosaurs deforming (hybrid)",
     "Paper (rebuild every frame): Lbvh 66.1 ms, Bvh 96.0, MedianBvh 67.7, KD-tree 96.4."},
    {"fig10", "Fig. 10: ray tracing of the deforming dinosaurs only (rt; the rest of the scene is invisible to the rays)",
     "Paper (rebuild every frame): Lbvh 29.8 ms, Bvh 49.8, MedianBvh 28.5, KD-tree 49.9."},
    {"fig12", "Fig. 12: SSR vs hybrid vs ray tracing along the walkthrough (simplified scene)",
     "Paper (KD-tree): hybrid close to SSR where the camera faces the side aisles (frames 207-1443, 3503-4224), "
     "below SSR but far above rt in the central corridor (1649-2576)."},
};

struct TableText {
  const char* figure;
  const char* title;
  std::map<int, std::pair<double, double>> paper;  // frame -> (SSR %, hybrid %)
};

const TableText kTables[] = {
    {"table1", "Table I: image quality against the rt reference, static scene",
     {{1800, {99.18, 99.76}}, {2100, {97.68, 99.85}}, {2300, {98.58, 99.96}}, {4400, {99.88, 99.97}}}},
    {"table2", "Table II: image quality against the rt reference, simplified scene with deforming dinosaurs",
     {{1800, {98.75, 99.66}}, {2100, {97.60, 99.75}}, {2300, {97.55, 99.93}}, {4400, {99.88, 99.97}}}},
};

std::string number(const nlohmann::json& value, const char* format = "{:.2f}") {
  if (value.is_number()) return fmt::format(fmt::runtime(format), value.get<double>());
  if (value.is_string()) return value.get<std::string>();
  return "-";
}

std::string field(const nlohmann::json& object, const char* key, const char* format = "{:.2f}") {
  return object.is_object() && object.contains(key) ? number(object[key], format) : "-";
}

std::vector<nlohmann::json> cells_of(const nlohmann::json& summary, const std::string& figure) {
  std::vector<nlohmann::json> cells;
  for (const nlohmann::json& cell : summary["cells"])
    if (cell["figure"] == figure) cells.push_back(cell);
  return cells;
}

void chart(std::string& text, const std::filesystem::path& out, const std::string& name, const std::string& caption) {
  if (!std::filesystem::exists(out / "charts" / (name + ".png"))) return;
  text += fmt::format("![{}](charts/{}.png)\n\n[SVG](charts/{}.svg)\n\n", caption, name, name);
}

void not_done_lines(std::string& text, const std::vector<nlohmann::json>& cells) {
  for (const nlohmann::json& cell : cells)
    if (cell["status"] != "done")
      text += fmt::format("- `{}` {}: {}\n", cell["id"].get<std::string>(), cell["status"].get<std::string>(),
                          cell["reason"].get<std::string>());
}

std::string memory_mib(const nlohmann::json& tracer) {
  if (!tracer.is_object() || !tracer.contains("memory_bytes")) return "-";
  return fmt::format("{:.1f}", tracer["memory_bytes"].get<double>() / (1024.0 * 1024.0));
}

void frame_time_section(std::string& text, const nlohmann::json& summary, const std::filesystem::path& out,
                        const FigureText& figure) {
  const std::vector<nlohmann::json> cells = cells_of(summary, figure.figure);
  if (cells.empty()) return;
  text += fmt::format("### {}\n\n{}\n\n", figure.title, figure.paper);
  const bool fig12 = std::string(figure.figure) == "fig12";
  text += fig12 ? "| cell | reflections | structure | update | frames | mean ms | median | p5 | p95 | rays/frame |\n"
                  "|---|---|---|---|---:|---:|---:|---:|---:|---:|\n"
                : "| structure | update | frames | mean ms | median | p5 | p95 | structure update ms | trace ms | "
                  "rays/frame | build ms | memory MiB |\n|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const nlohmann::json& cell : cells) {
    if (cell["status"] != "done") continue;
    const nlohmann::json& ms = cell["frame_ms"];
    const std::string update = cell["update"].get<std::string>().empty() ? "-" : cell["update"].get<std::string>();
    if (fig12) {
      text += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", cell["id"].get<std::string>(),
                          cell["reflections"].get<std::string>(),
                          cell["structure"].get<std::string>().empty() ? "-" : cell["structure"].get<std::string>(),
                          update, cell["frames"].get<int>(), field(ms, "mean"), field(ms, "median"), field(ms, "p5"),
                          field(ms, "p95"), number(cell["mean_rays_traced"], "{:.0f}"));
    } else {
      const nlohmann::json tracer = cell.contains("ray_tracer") ? cell["ray_tracer"] : nlohmann::json();
      text += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                          cell["structure"].get<std::string>(), update, cell["frames"].get<int>(), field(ms, "mean"),
                          field(ms, "median"), field(ms, "p5"), field(ms, "p95"),
                          field(cell["mean_ms"], "accel_update"), field(cell["mean_ms"], "trace"),
                          number(cell["mean_rays_traced"], "{:.0f}"), field(tracer, "build_ms", "{:.1f}"),
                          memory_mib(tracer));
    }
  }
  text += "\n";
  not_done_lines(text, cells);
  text += "\n";
  chart(text, out, figure.figure, figure.title);
}

void quality_section(std::string& text, const nlohmann::json& summary, const std::filesystem::path& out,
                     const TableText& table) {
  const std::vector<nlohmann::json> cells = cells_of(summary, table.figure);
  if (cells.empty()) return;
  text += fmt::format("### {}\n\n", table.title);
  for (const nlohmann::json& cell : cells) {
    if (cell["status"] != "done") continue;
    text += fmt::format("Cell `{}`: {}, rays by {}{}. Images: `{}/`.\n\n", cell["id"].get<std::string>(),
                        cell["scene"].get<std::string>(), cell["structure"].get<std::string>(),
                        cell["update"].get<std::string>().empty() ? "" : " (" + cell["update"].get<std::string>() + ")",
                        cell["images"].get<std::string>());
    text += "| frame | mode | colour buckets % | paper % | SSIM (luma) | PSNR dB | RMSE |\n"
            "|---:|---|---:|---:|---:|---:|---:|\n";
    for (const nlohmann::json& row : cell["rows"]) {
      const int frame = row["frame"].get<int>();
      const bool ssr = row["mode"] == "ssr";
      const auto paper = table.paper.find(frame);
      const std::string paper_text =
          paper == table.paper.end() ? "-" : fmt::format("{:.2f}", ssr ? paper->second.first : paper->second.second);
      text += fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", frame, row["mode"].get<std::string>(),
                          field(row["buckets_percent"], "mean", "{:.2f}"), paper_text, number(row["ssim_luma"], "{:.4f}"),
                          number(row["psnr_db"], "{:.2f}"), number(row["rmse"], "{:.3f}"));
    }
    text += "\n";
  }
  not_done_lines(text, cells);
  text += "\n";
  chart(text, out, table.figure, table.title);
}

// Fig. 11: a point per structure, rebuild time against render time (app/bench/fig11_points.h).
void fig11_section(std::string& text, const nlohmann::json& summary, const std::filesystem::path& out) {
  if (!summary.contains("fig11") || summary["fig11"].empty()) return;
  text += "### Fig. 11: rebuild time against render time per structure\n\n"
          "Paper (OptiX's guidance, confirmed by its runs): the KD-tree is the slowest to rebuild and the fastest to "
          "render, Lbvh the fastest to rebuild and the slowest to render. Render: mean frame time of the static "
          "full-scene cell; rebuild: mean structure update per frame of the deforming cell rebuilt every frame; "
          "build: the whole structure built once (every BLAS and the TLAS).\n\n"
          "| structure | render ms | render cell | rebuild ms | rebuild cell | build ms |\n"
          "|---|---:|---|---:|---|---:|\n";
  for (const nlohmann::json& point : summary["fig11"])
    text += fmt::format("| {} | {} | `{}` | {} | {} | {} |\n", point["structure"].get<std::string>(),
                        number(point["render_ms"]), point["render_cell"].get<std::string>(),
                        number(point["rebuild_ms"], "{:.3f}"),
                        point["rebuild_cell"].is_string() ? fmt::format("`{}`", point["rebuild_cell"].get<std::string>())
                                                          : std::string("-"),
                        number(point["build_ms"], "{:.1f}"));
  text += "\n";
  chart(text, out, "fig11", "Fig. 11");
}

// Fig. 4: the floor plan with the camera path (app/bench/floor_plan.h).
void fig4_section(std::string& text, const nlohmann::json& summary, const std::filesystem::path& out) {
  if (!summary.contains("floor_plan")) return;
  const nlohmann::json& plan = summary["floor_plan"];
  text += fmt::format("## Fig. 4: floor plan of {} with the camera path\n\n", plan["scene"].get<std::string>());
  text += fmt::format(
      "Seen from above (x across, z down the page), what stands between heights {:.2f} and {:.2f} (walking "
      "height) in cells of {:.2f}; the deforming meshes marked apart; the camera path and the light's path "
      "sampled every {} frames; the camera at the quality tables' frames:\n\n",
      plan["grid"]["slab"][0].get<double>(), plan["grid"]["slab"][1].get<double>(), plan["grid"]["cell"].get<double>(),
      plan["path_step"].get<int>());
  text += "| frame | camera (x, z) | looking at (x, z) |\n|---:|---|---|\n";
  for (const nlohmann::json& mark : plan["marked_frames"])
    text += fmt::format("| {} | {:.2f}, {:.2f} | {:.2f}, {:.2f} |\n", mark["frame"].get<int>(),
                        mark["camera"][0].get<double>(), mark["camera"][1].get<double>(),
                        mark["target"][0].get<double>(), mark["target"][1].get<double>());
  text += "\n";
  chart(text, out, "fig4", "Fig. 4: floor plan and camera path");
}

std::string cuda_text(const nlohmann::json& environment) {
  std::string text;
  for (const nlohmann::json& device : environment["cuda_devices"]) {
    if (!text.empty()) text += "; ";
    const int driver = device["driver_version"].get<int>();
    text += fmt::format("{} (sm_{}, CUDA driver {}.{})", device["name"].get<std::string>(),
                        device["compute_capability"].get<int>(), driver / 1000, (driver % 1000) / 10);
  }
  if (text.empty()) text = "none: " + environment.value("cuda_note", std::string("-"));
  return text;
}

void setup_section(std::string& text, const nlohmann::json& summary, const ReportExtras& extras) {
  const nlohmann::json& environment = summary["environment"];
  const nlohmann::json& settings = summary["settings"];
  std::string commit = environment["git_commit"].is_string() ? environment["git_commit"].get<std::string>() : "unknown";
  if (environment.value("git_dirty", false)) commit += " (with uncommitted changes)";
  text += "## Setup\n\n| | |\n|---|---|\n";
  text += fmt::format("| Date | {} |\n", extras.date);
  text += fmt::format("| glint | {} |\n", environment["glint_version"].get<std::string>());
  text += fmt::format("| Commit | {} |\n", commit);
  text += fmt::format("| GL renderer | {} |\n", environment["gl"]["renderer"].get<std::string>());
  text += fmt::format("| GL version (driver) | {} |\n", environment["gl"]["version"].get<std::string>());
  text += fmt::format("| Pass timing | {} |\n", environment["gl"]["pass_timing"].get<std::string>());
  text += fmt::format("| CUDA devices | {} |\n", cuda_text(environment));
  text += fmt::format("| Command | `{}` |\n", summary["command"].get<std::string>());
  text += fmt::format("| Scenes | full: {}; simplified: {} |\n", settings["scene"].get<std::string>(),
                      settings["simple_scene"].get<std::string>());
  text += fmt::format("| Resolution | {}x{} |\n", settings["width"].get<int>(), settings["height"].get<int>());
  text += fmt::format("| Frames | walkthrough frames 0 to {}, every {} (--stride), {} warm-up frame(s) per cell; "
                      "quality tables at the paper's frames |\n",
                      settings["frames"].get<int>() - 1, settings["stride"].get<int>(), settings["warmup_frames"].get<int>());
  // Settings of runs made before --shadows and --gbuffer existed lack them: those ran cube and raster.
  const std::string shadows = settings.value("shadows", std::string("cube"));
  const int cube_size = settings["shadow_map_size"].get<int>();
  text += shadows == "rt" ? std::string("| Shadows | rt: a shadow ray per lit pixel and per reflection hit, no cube map |\n")
                          : fmt::format("| Shadows | {}: cube map {}x{} per face{} |\n", shadows, cube_size, cube_size,
                                        shadows == "hybrid" ? " at half that size, shadow rays where it is uncertain" : "");
  text += fmt::format("| G-buffer | {} |\n", settings.value("gbuffer", std::string("raster")));
  text += fmt::format(
      "| Frame time | steady state: the time between consecutive frames' completions on the GPU with up to three "
      "frames in flight (deformation, structure update and every pass included); charts average intervals of {} "
      "measured frames, as the paper averages 10-frame intervals |\n\n",
      settings["interval_frames"].get<int>());
  text += "Backends:\n\n";
  for (const nlohmann::json& backend : summary["backends"])
    text += backend["available"].get<bool>()
                ? fmt::format("- `{}`: available\n", backend["name"].get<std::string>())
                : fmt::format("- `{}`: skipped, {}\n", backend["name"].get<std::string>(),
                              backend["reason"].get<std::string>());
  text += "\n";
}

}  // namespace

std::string bench_report_markdown(const nlohmann::json& summary, const std::filesystem::path& out,
                                  const ReportExtras& extras) {
  std::string text = "# glint bench: the paper's experiments\n\n";
  text +=
      "The experiment matrix of Macedo & Rodrigues (Figs. 5, 7-10, 12, Tables I-II) measured with glint; the "
      "paper's numbers (GTX 780 Ti, OptiX 3/4, 1280x720, 4900 frames) are quoted beside each figure. Raw "
      "per-frame rows are in `cells/<cell>.csv`, every number of this page in `summary.json`.\n\n";
  setup_section(text, summary, extras);
  text += mpi::distribution_markdown(summary);  // a run shared over MPI ranks: how
  fig4_section(text, summary, out);

  text += "## Cells\n\n| cell | status | frames | mean ms | median | p95 |\n|---|---|---:|---:|---:|---:|\n";
  for (const nlohmann::json& cell : summary["cells"]) {
    const bool timed = cell["status"] == "done" && cell["kind"] == "frame_times";
    const bool quality = cell["status"] == "done" && cell["kind"] == "quality";
    text += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", cell["id"].get<std::string>(),
                        cell["status"].get<std::string>(),
                        timed ? std::to_string(cell["frames"].get<int>())
                              : quality ? std::to_string(cell["rows"].size() / 2) : "-",
                        timed ? field(cell["frame_ms"], "mean") : "-", timed ? field(cell["frame_ms"], "median") : "-",
                        timed ? field(cell["frame_ms"], "p95") : "-");
  }
  text += "\n";

  text += "## Frame times\n\n";
  for (const FigureText& figure : kFigures) {
    // Fig. 11 sums up Figs. 5-10 per structure; the paper puts it before Fig. 12.
    if (std::string(figure.figure) == "fig12") fig11_section(text, summary, out);
    frame_time_section(text, summary, out, figure);
  }
  text += "## Image quality\n\n";
  text +=
      "Colour buckets are the paper's measure (sums of each channel compared with the reference's; blind to where "
      "colours are), so SSIM, PSNR and RMSE are given beside them (docs/metrics.md).\n\n";
  for (const TableText& table : kTables) quality_section(text, summary, out, table);

  text += "## Skipped and failed cells\n\n";
  std::size_t not_done = 0;
  for (const nlohmann::json& cell : summary["cells"]) not_done += cell["status"] != "done" ? 1 : 0;
  if (not_done == 0) {
    text += "None.\n\n";
  } else {
    text += "| cell | status | reason |\n|---|---|---|\n";
    for (const nlohmann::json& cell : summary["cells"])
      if (cell["status"] != "done")
        text += fmt::format("| `{}` | {} | {} |\n", cell["id"].get<std::string>(), cell["status"].get<std::string>(),
                            cell["reason"].get<std::string>());
    text += "\n";
  }

  text += "## Charts\n\n";
  text += extras.chart_note.empty()
              ? "Made by `plot_bench.py` (a copy of glint's tools/plot_bench.py) from summary.json; to make them again: "
                "`python3 plot_bench.py .` in this folder.\n"
              : extras.chart_note + "\n";
  return text;
}

}  // namespace glint::bench
