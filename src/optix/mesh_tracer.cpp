#include "optix/mesh_tracer.h"

#include "core/error.h"
#include "core/stopwatch.h"
#include "cuda/cuda_stream_events.h"
#include "optix/device_context.h"
#include "optix/host_trace.h"
#include "optix/trace_pipeline.h"
#include "optix/triangle_gas.h"

#include <span>

namespace glint::optix {
namespace {

std::span<const vec3> mesh_positions(const accel::TriangleMesh& mesh) {
  const std::size_t count = mesh.indices ? mesh.vertex_count : 3 * static_cast<std::size_t>(mesh.triangle_count);
  return {mesh.positions, count};
}

std::span<const std::uint32_t> mesh_indices(const accel::TriangleMesh& mesh) {
  if (!mesh.indices) return {};
  return {mesh.indices, 3 * static_cast<std::size_t>(mesh.triangle_count)};
}

}  // namespace

struct OptixMeshTracer::State {
  explicit State(BuildPreference build_preference) : preference(build_preference) {}

  DeviceContext context;
  TraceClosestPipeline pipeline{context.get(), context.validation()};
  cuda::CudaStream stream;
  BuildPreference preference;
  TriangleGas gas;
  cuda::DeviceBuffer<std::byte> scratch;
  cuda::DeviceBuffer<std::uint64_t> compacted_size{1};
  HostTraceStaging host_trace;
  bool built = false;
};

OptixMeshTracer::OptixMeshTracer(BuildPreference preference)
    : state_(std::make_unique<State>(preference)) {}

OptixMeshTracer::~OptixMeshTracer() {
  if (state_) cudaStreamSynchronize(state_->stream.get());  // not checked: work in flight must end first
}

double OptixMeshTracer::build(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream.get()));
  s.built = false;
  s.gas.set_geometry(mesh_positions(mesh), mesh_indices(mesh));
  const bool compact = s.preference == BuildPreference::fast_trace;
  const Stopwatch watch;
  s.gas.build(s.context.get(), gas_build_flags(s.preference, compact, false), s.scratch, s.stream.get(),
              compact ? s.compacted_size.data() : nullptr);
  if (compact) {
    const std::uint64_t bytes = s.compacted_size.download()[0];  // synchronous: after the build
    s.gas.compact(s.context.get(), static_cast<std::size_t>(bytes), s.stream.get());
  }
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream.get()));
  s.built = true;
  return watch.elapsed_ms();
}

double OptixMeshTracer::refit(const accel::TriangleMesh& mesh) {
  State& s = *state_;
  if (!s.built) fail("optix accel-bench: refit before build");
  if (mesh.triangle_count != s.gas.triangle_count())
    fail("optix accel-bench: refit of {} triangles, built over {}", mesh.triangle_count, s.gas.triangle_count());
  s.gas.upload_positions(mesh_positions(mesh), s.stream.get());
  if (!s.gas.updatable()) s.gas.build(s.context.get(), gas_build_flags(s.preference, false, true), s.scratch, s.stream.get());
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream.get()));
  const Stopwatch watch;
  s.gas.update(s.context.get(), s.scratch, s.stream.get());
  GLINT_CUDA_CHECK(cudaStreamSynchronize(s.stream.get()));
  return watch.elapsed_ms();
}

double OptixMeshTracer::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) {
  State& s = *state_;
  if (!s.built) fail("optix accel-bench: trace before build");
  return s.host_trace.trace(s.pipeline, s.gas.handle(), rays, hits, s.stream.get());
}

std::size_t OptixMeshTracer::structure_bytes() const { return state_->gas.structure_bytes(); }

}  // namespace glint::optix
