// The GPU builders' names: plain C++, in builds with and without CUDA (the CLI and the CPU-only
// tests name builders too).
#include "cuda/gpu_bvh_host.h"

#include "core/error.h"

#include <string>

namespace glint::cuda {

const char* gpu_builder_name(GpuBvhBuilder builder) {
  switch (builder) {
    case GpuBvhBuilder::lbvh: return "lbvh";
    case GpuBvhBuilder::ploc: return "ploc";
  }
  return "unknown";
}

GpuBvhBuilder parse_gpu_builder(std::string_view name) {
  for (const GpuBvhBuilder builder : kAllGpuBvhBuilders)
    if (name == gpu_builder_name(builder)) return builder;
  std::string known;
  for (const GpuBvhBuilder builder : kAllGpuBvhBuilders) {
    if (!known.empty()) known += ", ";
    known += gpu_builder_name(builder);
  }
  fail("cuda: unknown GPU BVH builder '{}' (known: {})", name, known);
}

}  // namespace glint::cuda
