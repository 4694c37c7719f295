#pragma once
// GPU memory in use on the current context's device, for long-run checks (timings.csv's
// gpu_memory_used_mb column): GL_NVX_gpu_memory_info's total minus currently available dedicated
// memory, which counts every allocation on the GPU (GL, CUDA, other processes), read without
// creating a CUDA context. nullopt on drivers without the extension (Mesa, AMD).
#include <cstdint>
#include <optional>

namespace glint {

// Needs a current GL context.
std::optional<std::uint64_t> gpu_memory_used_bytes();

}  // namespace glint
