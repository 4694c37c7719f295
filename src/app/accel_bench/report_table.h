#pragma once
// accel-bench's text output: the structures table and the deformation table.
#include "app/accel_bench/bench_run.h"

#include <string>

namespace glint::accel_bench {

// Columns: structure, build ms, Mprims/s, nodes, MB, SAH, Mrays/s, x embree-medium, rays whose hits
// disagree with the reference's; "-" where a value does not exist (Embree's nodes and SAH, an
// untraced brute force, the reference's disagreements). Then, when the scene deforms, per
// structure: rebuild ms, refit ms per frame, refit speed-up, SAH drift and the rays on which the
// refitted copy disagrees with the rebuilt one.
std::string format_report_table(const BenchReport& report);

}  // namespace glint::accel_bench
