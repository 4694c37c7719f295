#pragma once
// The two ways the cuda backend's closest-hit kernel walks a ray list (cuda/gpu_trace.h), measured
// against each other in docs/perf.md; both give the same hits.
//  - one_ray_per_thread: a thread per ray slot; a block retires when its slowest ray is done.
//  - persistent: Aila & Laine 2009's persistent threads: just enough warps to fill the GPU, each
//    taking the next 32 rays from a global counter whenever it is done, so warps that drew short
//    rays take more instead of idling behind long ones.
// A cuda backend option (cuda::CudaTracerOptions, cuda/cuda_ray_tracer.h), not rt's. Plain C++ (no
// CUDA headers), header-only.
#include "core/enum_names.h"

#include <string_view>

namespace glint::cuda {

enum class TraceKernel { one_ray_per_thread, persistent };

inline constexpr EnumNames<TraceKernel, 2> kTraceKernelNames{
    "trace kernel", {{TraceKernel::one_ray_per_thread, "one-ray-per-thread"}, {TraceKernel::persistent, "persistent"}}};

// "one-ray-per-thread", "persistent".
inline std::string_view trace_kernel_name(TraceKernel kernel) { return kTraceKernelNames.name_of(kernel); }

// The kernel the cuda backend traces with (the faster one on the H100, docs/perf.md).
inline constexpr TraceKernel kDefaultTraceKernel = TraceKernel::one_ray_per_thread;

}  // namespace glint::cuda
