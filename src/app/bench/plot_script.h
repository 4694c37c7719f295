#pragma once
// tools/plot_bench.py, embedded at build time, and running it on a bench folder: `glint bench`
// copies the script next to its results (so they can be plotted again by hand, without the source
// tree) and runs it when python3 with matplotlib is there.
#include <filesystem>
#include <string>
#include <string_view>

namespace glint::bench {

extern const std::string_view kPlotBenchScript;

// Writes DIR/plot_bench.py and runs `python3 DIR/plot_bench.py DIR` (PATH's python3, else
// /usr/bin/python3 when only that one has matplotlib), which reads summary.json and
// writes charts/*.png and *.svg. Returns "" when the charts were made, otherwise one line saying
// why not and how to make them by hand (python3 or matplotlib missing, the script failed).
std::string plot_bench_charts(const std::filesystem::path& out);

}  // namespace glint::bench
