#pragma once
// accel-bench's JSON output: everything in the report plus the machine it ran on.
#include "app/accel_bench/bench_run.h"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace glint::accel_bench {

struct MachineInfo {
  std::string cpu;       // "model name" of /proc/cpuinfo, "unknown" when unreadable
  int threads = 0;       // TBB threads the benchmark ran with
  std::string date;      // UTC, ISO 8601
};

// The CPU model, `threads` and the current date.
MachineInfo current_machine(int threads);

nlohmann::json report_json(const BenchReport& report, const MachineInfo& machine);

// Writes `json` to `path` through a temporary file in the same folder and a rename, so a reader
// never sees half a file. glint::Error naming the path when it cannot be written.
void write_json_atomically(const std::filesystem::path& path, const nlohmann::json& json);

// Fails at once where write_json_atomically(path, ...) would fail at the end of a long run: `path`
// is a folder, its folder is missing or is a file, or no file can be created in it (a temporary is
// created there and removed). glint::Error naming the path.
void check_json_path(const std::filesystem::path& path);

}  // namespace glint::accel_bench
