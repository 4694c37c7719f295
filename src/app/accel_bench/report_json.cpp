#include "app/accel_bench/report_json.h"

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/utc_timestamp.h"

#include <chrono>
#include <ctime>
#include <fstream>

namespace glint::accel_bench {
namespace {

template <typename T>
nlohmann::json or_null(const std::optional<T>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::string cpu_model() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const size_t start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? std::string("unknown") : line.substr(start);
  }
  return "unknown";
}


}  // namespace

MachineInfo current_machine(int threads) { return {cpu_model(), threads, utc_timestamp()}; }

nlohmann::json report_json(const BenchReport& report, const MachineInfo& machine) {
  nlohmann::json j;
  j["machine"] = {{"cpu", machine.cpu}, {"threads", machine.threads}, {"date", machine.date}};
  j["scene"] = {{"name", report.scene},
                {"triangles", report.scene_triangles},
                {"vertices", report.scene_vertices},
                {"instances", report.instances}};
  j["rays"] = {{"kind", std::string(ray_kind_name(report.ray_kind))}, {"frames", report.frames}, {"width", report.width},
               {"height", report.height}, {"count", report.ray_count}, {"hits", report.ray_hits},
               {"reference", report.reference}};
  j["build_runs"] = report.build_runs;
  j["structures"] = nlohmann::json::array();
  for (const StructureResult& r : report.structures) {
    nlohmann::json row = {{"name", r.name},
                          {"build_ms", r.build_ms},
                          {"first_build_ms", r.first_build_ms},
                          {"mprims_per_s", r.mprims_per_s},
                          {"nodes", or_null(r.nodes)},
                          {"memory_bytes", r.memory_bytes},
                          {"sah", or_null(r.sah)},
                          {"mrays_per_s", or_null(r.mrays_per_s)},
                          {"ratio_to_embree_medium", or_null(r.ratio_to_embree_medium)}};
    if (!r.skipped.empty()) row["not_traced"] = r.skipped;
    row["disagreements"] = r.disagreements;
    row["edge_grazes"] = r.edge_grazes;
    row["disagreement"] = r.hit_problem.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.hit_problem);
    j["structures"].push_back(row);
  }
  j["deformation"] = {{"meshes", report.deformable_meshes},
                      {"triangles", report.deformable_triangles},
                      {"frames", report.deform_frames},
                      {"structures", nlohmann::json::array()}};
  for (const DeformResult& d : report.deform)
    j["deformation"]["structures"].push_back({{"name", d.name},
                                              {"rebuild_ms", d.rebuild_ms},
                                              {"refit_ms", or_null(d.refit_ms)},
                                              {"sah_drift", or_null(d.sah_drift)},
                                              {"disagreements", or_null(d.disagreements)},
                                              {"disagreement", d.hit_problem.empty() ? nlohmann::json(nullptr)
                                                                                     : nlohmann::json(d.hit_problem)}});
  return j;
}

void write_json_atomically(const std::filesystem::path& path, const nlohmann::json& json) {
  write_file_atomically(path, json.dump(2) + "\n");
}

void check_json_path(const std::filesystem::path& path) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) fail("cannot write '{}': it is a folder", path.string());
  const AtomicFileWriter probe(path);  // its temporary is removed again, uncommitted, when it goes
}

}  // namespace glint::accel_bench
