#include "app/accel_bench/report_table.h"

#include <fmt/format.h>

#include <optional>

namespace glint::accel_bench {
namespace {

template <typename T>
std::string or_dash(const std::optional<T>& value, const char* format) {
  return value ? fmt::format(fmt::runtime(format), *value) : std::string("-");
}

}  // namespace

std::string format_report_table(const BenchReport& report) {
  std::string out;
  out += fmt::format("scene {} ({} triangles, {} instances), {} {} rays", report.scene, report.scene_triangles,
                     report.instances, report.ray_count, ray_kind_name(report.ray_kind));
  if (report.ray_kind != RayKind::random)
    out += fmt::format(" from frames {} at {}x{}", fmt::join(report.frames, ","), report.width, report.height);
  out += fmt::format(", {} hit; hits checked against {}\n\n", report.ray_hits, report.reference);
  out += fmt::format("{:<16} {:>10} {:>9} {:>10} {:>8} {:>8} {:>9} {:>8} {:>8}\n", "structure", "build ms",
                     "Mprims/s", "nodes", "MB", "SAH", "Mrays/s", "x medium", "disagree");
  for (const StructureResult& r : report.structures) {
    // The reference is not checked against itself, and a structure that was not traced not at all.
    const bool checked = r.mrays_per_s && r.name != report.reference;
    out += fmt::format("{:<16} {:>10.1f} {:>9.2f} {:>10} {:>8.1f} {:>8} {:>9} {:>8} {:>8}", r.name, r.build_ms,
                       r.mprims_per_s, or_dash(r.nodes, "{}"), static_cast<double>(r.memory_bytes) / (1024.0 * 1024.0),
                       or_dash(r.sah, "{:.1f}"), or_dash(r.mrays_per_s, "{:.2f}"),
                       or_dash(r.ratio_to_embree_medium, "{:.2f}"),
                       or_dash(checked ? std::optional<size_t>(r.disagreements) : std::nullopt, "{}"));
    if (!r.skipped.empty()) out += fmt::format("  (not traced: {})", r.skipped);
    if (r.edge_grazes != 0) out += fmt::format("  ({} edge-grazing rays disagree with the reference)", r.edge_grazes);
    out += '\n';
  }
  if (report.deform.empty()) return out;
  out += fmt::format("\ndeformation: {} ({} triangles), {} frames; mean ms per frame\n",
                     fmt::join(report.deformable_meshes, ", "), report.deformable_triangles, report.deform_frames);
  out += fmt::format("{:<16} {:>10} {:>9} {:>9} {:>9} {:>8}\n", "structure", "rebuild", "refit", "speed-up",
                     "SAH drift", "disagree");
  for (const DeformResult& d : report.deform) {
    const std::optional<double> speedup =
        d.refit_ms && *d.refit_ms > 0.0 ? std::optional<double>(d.rebuild_ms / *d.refit_ms) : std::nullopt;
    out += fmt::format("{:<16} {:>10.2f} {:>9} {:>9} {:>9} {:>8}\n", d.name, d.rebuild_ms, or_dash(d.refit_ms, "{:.2f}"),
                       or_dash(speedup, "{:.1f}"), or_dash(d.sah_drift, "{:.3f}"), or_dash(d.disagreements, "{}"));
  }
  return out;
}

}  // namespace glint::accel_bench
