#pragma once
// Fig. 11 of the paper ("default behavior of the acceleration structures"): each structure's rebuild
// time against its render time, from the cells' statistics in summary.json. The paper's finding: the
// kd-tree is the slowest to rebuild and the fastest to render, Lbvh the reverse.
#include <nlohmann/json.hpp>

namespace glint::bench {

// One point per structure (in the cells' order) that has a render time, as
//   {"structure", "render_ms", "render_cell", "rebuild_ms", "rebuild_cell", "build_ms"}:
// render_ms is the mean frame time of its static full-scene cell (fig5; fig8 when fig5 was not done),
// rebuild_ms the mean structure update time of its deforming full-scene cell with update policy
// rebuild (fig7; fig9 otherwise; null when neither was done), build_ms the tracer's whole build
// (every BLAS and the TLAS) in that static cell (null when unknown). `cells` is summary.json's "cells".
nlohmann::json fig11_points(const nlohmann::json& cells);

}  // namespace glint::bench
