#pragma once
// How much memory this process holds, for long-run checks (timings.csv's resident_mb column and the
// soak runs of docs/reliability.md): resident set size from /proc/self/statm (Linux).
#include <cstdint>
#include <optional>

namespace glint {

// Bytes of this process resident in RAM now; nullopt where /proc/self/statm cannot be read.
std::optional<std::uint64_t> resident_memory_bytes();

}  // namespace glint
