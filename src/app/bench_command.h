#pragma once
// `glint bench --experiment paper --out DIR`: the paper's experiment matrix (Figs. 5, 7-10, 12,
// Tables I-II) on the walkthrough, for every backend and structure asked for, with raw CSVs per
// cell, summary.json, charts (tools/plot_bench.py) and report.md. An interrupted run resumes where it
// stopped. docs/bench.md describes the cells and the outputs.
#include <CLI/CLI.hpp>

#include <set>
#include <string>
#include <vector>

namespace glint {

struct BenchOptions {
  std::string experiment;                          // "paper", "adaptive" or "glossy"
  std::string scene = "atrium";                    // Figs. 5, 7 and Table I
  std::string simple_scene = "atrium-simple";      // Figs. 8, 9, 10, 12 and Table II
  std::string backends = "cpu,embree,cuda,optix";
  std::string accels = "median,sah,sbvh,lbvh,trbvh,ploc";  // builders of the cpu and cuda backends
  std::string updates = "rebuild,refit";           // policies of the deforming cells
  int frames = 4900;                               // walkthrough frames considered (0 .. frames - 1)
  int stride = 1;                                  // every stride-th of them is measured
  int width = 1280;
  int height = 720;
  int warmup = 3;                                  // unrecorded frames before each cell's first
  int interval = 10;                               // measured frames per interval mean
  int shadow_map_size = 1024;
  std::string gbuffer = "raster";                  // raster|visibility, as glint render --gbuffer
  std::string shadows = "cube";                    // cube|rt|hybrid, as glint render --shadows
  // --experiment glossy (app/bench/glossy_experiment.h): samples per pixel of the converged reference,
  // and the frames of each flicker series (the walkthrough's before a measured frame; the still
  // camera's warm-up and its measured series)
  int reference_spp = 256;
  int flicker_frames = 16;
  std::string time_limit;  // paper: no cell starts after this long (app/time_limit.h); empty: none
  bool quick = false;   // smoke run: tiny resolution, few frames, cpu backend, atrium-simple
  bool no_plot = false;
  std::string out;
  std::string command_line;   // for summary.json and the report, set by the CLI
  std::set<std::string> given;  // long names of the flags given on the command line
};

void add_bench_command(CLI::App& app, BenchOptions& options);
int run_bench_command(const BenchOptions& options);

// What --quick changes: every setting the user did not give explicitly.
BenchOptions with_quick_defaults(BenchOptions options);

// A comma-separated flag value as its items (spaces around items dropped). glint::Error naming
// `flag` for an empty list, an empty item, an item repeated, or one not in `known` (when given).
std::vector<std::string> parse_name_list(const std::string& flag, const std::string& text,
                                         const std::vector<std::string>& known = {});

}  // namespace glint
