// RayTracedReflections picks its trace step once, by where the backend traces
// (render/reflection_trace_step.h): CPU backends trace host-mapped buffers after the CPU waited for
// the ray list, CUDA backends trace the GL buffers mapped into CUDA, the gl backend traces them in
// compute shaders. The rule must send every backend to the step whose buffers it can read.
#include "render/reflection_trace_step.h"

#include "../gl/gl_test_context.h"
#include "backends/registry.h"
#include "cuda/device_query.h"
#include "render/device_reflection_trace.h"
#include "render/gl_reflection_trace.h"
#include "render/host_reflection_trace.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace glint::render {
namespace {

using ReflectionTraceStepTest = testing::GlTest;

// The step make_reflection_trace_step chooses for `backend`, over buffers in the memory
// reflection_ray_memory chooses; `memory` receives that choice.
template <typename Step>
bool chooses(const std::string& backend, RayHitMemory& memory) {
  const std::unique_ptr<rt::RayTracer> tracer = backends::make_ray_tracer(backend);
  memory = reflection_ray_memory(*tracer);
  RayHitBuffers buffers(64, memory);
  const std::unique_ptr<ReflectionTraceStep> step = make_reflection_trace_step(*tracer, buffers, nullptr);
  return dynamic_cast<Step*>(step.get()) != nullptr;
}

TEST_F(ReflectionTraceStepTest, CpuBackendsTraceHostMappedBuffers) {
  for (const std::string backend : {"cpu", "embree"}) {
    RayHitMemory memory{};
    EXPECT_TRUE(chooses<HostReflectionTrace>(backend, memory)) << backend;
    EXPECT_EQ(memory, RayHitMemory::host_mapped) << backend;
  }
}

TEST_F(ReflectionTraceStepTest, GlBackendTracesInItsComputeShaders) {
  RayHitMemory memory{};
  EXPECT_TRUE(chooses<GlReflectionTrace>("gl", memory));
  EXPECT_EQ(memory, RayHitMemory::device);
}

TEST_F(ReflectionTraceStepTest, CudaBackendTracesTheBuffersMappedIntoCuda) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  RayHitMemory memory{};
  EXPECT_TRUE(chooses<DeviceReflectionTrace>("cuda", memory));
  EXPECT_EQ(memory, RayHitMemory::device);
}

}  // namespace
}  // namespace glint::render
