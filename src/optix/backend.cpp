#include "optix/backend.h"
#include "optix/build_preference.h"

#include "core/error.h"
#include "core/stopwatch.h"
#include "cuda/cuda_stream_events.h"
#include "cuda/cuda_span.h"
#include "cuda/tracer_gpu_times.h"
#include "optix/result_check.h"
#include "optix/device_context.h"
#include "optix/host_trace.h"
#include "optix/instance_accel.h"
#include "optix/ray_records.h"
#include "optix/trace_pipeline.h"
#include "optix/triangle_gas.h"
#include "rt/scene_shape.h"

#include <algorithm>
#include <mutex>
#include <vector>

namespace glint::optix {
namespace {

struct MeshStructure {
  TriangleGas gas;
  bool deformable = false;
};

// The IAS follows the GAS preference; it is rebuilt, never updated or compacted.
unsigned int ias_build_flags(BuildPreference preference) {
  return preference == BuildPreference::fast_trace ? OPTIX_BUILD_FLAG_PREFER_FAST_TRACE
                                                            : OPTIX_BUILD_FLAG_PREFER_FAST_BUILD;
}

}  // namespace

struct OptixRayTracer::State {
  DeviceContext context;
  TraceClosestPipeline pipeline{context.get(), context.validation()};
  cuda::CudaStream stream;
  // Device-side traces and structure updates, timed for gpu_ms; stats() reads the last update's time.
  cuda::TracerGpuTimes<cuda::CudaSpan> timed{"rt optix"};

  BuildPreference preference = BuildPreference::fast_trace;
  std::vector<MeshStructure> meshes;
  std::vector<std::uint32_t> instance_meshes;
  std::vector<OptixInstance> instances;
  InstanceAccel ias;
  // Temp memory of every GAS and IAS build and update (one stream orders them), sized at build().
  cuda::DeviceBuffer<std::byte> scratch;
  rt::SceneShape shape;
  bool built = false;

  double build_ms = 0.0;
  std::size_t rebuilds = 0, refits = 0;

  std::mutex host_trace_mutex;  // trace_closest is const and may be called from several threads
  HostTraceStaging host_trace;

  void require_built(const char* what) const {
    if (!built) fail("rt optix: {} before build()", what);
  }

  // A device-side query (`params` names its output) over the IAS, between the trace events.
  rt::GpuTicket launch_device(OptixLaunchParams& params, const accel::Ray* rays, const std::uint32_t* ray_count,
                              std::uint32_t capacity) {
    params.root = ias.handle();
    params.rays = as_ray_records(rays);
    params.ray_count = ray_count;
    params.capacity = capacity;
    const rt::GpuTicket ticket = cuda::start_span(timed, stream.get());
    pipeline.launch(params, stream.get());
    cuda::stop_span(timed, ticket, stream.get());
    return ticket;
  }

  // Dirty GASes rebuilt or refitted, then the IAS rebuilt over the (possibly new) GAS handles; all
  // enqueued on the stream.
  void update_structures(std::span<const std::uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
    for (const std::uint32_t m : dirty_meshes) {
      TriangleGas& gas = meshes[m].gas;
      if (policy == rt::UpdatePolicy::rebuild) {
        gas.build(context.get(), gas_build_flags(preference, false, false), scratch, stream.get());
        ++rebuilds;
      } else if (!gas.updatable()) {
        // Built without ALLOW_UPDATE (a static mesh, or a rebuild-policy frame before): rebuilt once
        // with it, then updated from the next frame on.
        gas.build(context.get(), gas_build_flags(preference, false, true), scratch, stream.get());
        ++rebuilds;
      } else {
        gas.update(context.get(), scratch, stream.get());
        ++refits;
      }
    }
    for (std::size_t i = 0; i < instances.size(); ++i)
      instances[i].traversableHandle = meshes[instance_meshes[i]].gas.handle();
    ias.build(context.get(), instances, ias_build_flags(preference), scratch, stream.get());
  }
};

OptixRayTracer::OptixRayTracer() : state_(std::make_unique<State>()) {}

OptixRayTracer::~OptixRayTracer() {
  if (state_) cudaStreamSynchronize(state_->stream.get());  // not checked: work in flight must end first
}

void OptixRayTracer::build(const Scene& scene, const rt::AccelOptions& options) {
  scene.validate();
  State& s = *state_;
  const Stopwatch watch;
  const cudaStream_t stream = s.stream.get();
  const OptixDeviceContext context = s.context.get();
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));  // nothing in flight may use the old structures
  s.built = false;
  s.preference = build_preference_of(options.backend_structure);
  s.shape = rt::scene_shape(scene);
  s.meshes.clear();
  s.meshes.resize(scene.meshes.size());

  // Buffers first: a deformable mesh's output holds either flag set (update() may rebuild it with or
  // without ALLOW_UPDATE), and the scratch any build or update, so later frames allocate nothing.
  std::size_t scratch_bytes = 0;
  for (std::size_t m = 0; m < scene.meshes.size(); ++m) {
    MeshStructure& mesh = s.meshes[m];
    mesh.deformable = scene.meshes[m].deformable;
    mesh.gas.set_geometry(scene.meshes[m].positions, scene.meshes[m].indices);
    if (!mesh.deformable) continue;
    for (const bool allow_update : {false, true}) {
      const OptixAccelBufferSizes sizes =
          mesh.gas.buffer_sizes(context, gas_build_flags(s.preference, false, allow_update));
      mesh.gas.reserve_output(sizes.outputSizeInBytes);
      scratch_bytes = std::max({scratch_bytes, sizes.tempSizeInBytes, sizes.tempUpdateSizeInBytes});
    }
  }
  s.scratch.resize(std::max(scratch_bytes, s.scratch.size()));

  // Static meshes are compacted (fast trace only); deformable ones are built ready to be updated.
  const bool compact = s.preference == BuildPreference::fast_trace;
  cuda::DeviceBuffer<std::uint64_t> compacted_sizes(s.meshes.size());
  for (std::size_t m = 0; m < s.meshes.size(); ++m) {
    MeshStructure& mesh = s.meshes[m];
    const bool compact_this = compact && !mesh.deformable;
    mesh.gas.build(context, gas_build_flags(s.preference, compact_this, mesh.deformable), s.scratch, stream,
                   compact_this ? compacted_sizes.data() + m : nullptr);
  }
  if (compact) {
    GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
    const std::vector<std::uint64_t> sizes = compacted_sizes.download();
    for (std::size_t m = 0; m < s.meshes.size(); ++m)
      if (!s.meshes[m].deformable) s.meshes[m].gas.compact(context, static_cast<std::size_t>(sizes[m]), stream);
  }

  s.instance_meshes.clear();
  s.instances.clear();
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    s.instance_meshes.push_back(instance.mesh);
    s.instances.push_back(
        make_instance(instance.transform, static_cast<unsigned int>(i), s.meshes[instance.mesh].gas.handle()));
  }
  s.ias.build(context, s.instances, ias_build_flags(s.preference), s.scratch, stream);
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
  s.build_ms = watch.elapsed_ms();
  s.timed.forget_update();
  s.rebuilds = s.refits = 0;
  s.built = true;
}

void OptixRayTracer::update(const Scene& scene, std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  State& s = *state_;
  s.require_built("update()");
  rt::check_update(name(), s.shape, scene, dirty_meshes);
  const cudaStream_t stream = s.stream.get();
  const rt::GpuTicket ticket = cuda::start_span(s.timed, stream);
  for (const std::uint32_t m : dirty_meshes) s.meshes[m].gas.upload_positions(scene.meshes[m].positions, stream);
  // Transforms may have moved too (animated instances): re-read them all, the IAS is small.
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    s.instances[i] = make_instance(scene.instances[i].transform, static_cast<unsigned int>(i), 0);
  s.update_structures(dirty_meshes, policy);
  cuda::stop_span(s.timed, ticket, stream);
  s.timed.opened_update(ticket);
  // The copies read `scene`'s vertices, which the caller may change once this returns.
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream));
}

void OptixRayTracer::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const {
  State& s = *state_;
  s.require_built("trace_closest()");
  const std::lock_guard lock(s.host_trace_mutex);
  (void)s.host_trace.trace(s.pipeline, s.ias.handle(), rays, hits, s.stream.get());
}

void OptixRayTracer::trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const {
  State& s = *state_;
  s.require_built("trace_any()");
  const std::lock_guard lock(s.host_trace_mutex);
  (void)s.host_trace.trace_any(s.pipeline, s.ias.handle(), rays, occluded, s.stream.get());
}

rt::RayTracerStats OptixRayTracer::stats() const {
  State& s = *state_;
  rt::RayTracerStats stats;
  stats.backend = std::string(name());
  stats.build_ms = s.build_ms;
  stats.last_update_ms = s.timed.last_update_ms();
  stats.rebuilds = s.rebuilds;
  stats.refits = s.refits;
  std::uint64_t bytes = s.ias.bytes();
  for (const MeshStructure& mesh : s.meshes) bytes += mesh.gas.structure_bytes() + mesh.gas.geometry_bytes();
  stats.memory_bytes = bytes;
  return stats;
}

void* OptixRayTracer::stream() { return state_->stream.get(); }

rt::GpuTicket OptixRayTracer::trace_closest_device(const accel::Ray* rays, accel::Hit* hits,
                                                   const uint32_t* ray_count, uint32_t capacity) {
  State& s = *state_;
  s.require_built("trace_closest_device()");
  OptixLaunchParams params;
  params.hits = as_hit_records(hits);
  return s.launch_device(params, rays, ray_count, capacity);
}

rt::GpuTicket OptixRayTracer::trace_any_device(const accel::Ray* rays, uint32_t* occluded, const uint32_t* ray_count,
                                               uint32_t capacity) {
  State& s = *state_;
  s.require_built("trace_any_device()");
  OptixLaunchParams params;
  params.occluded = occluded;
  return s.launch_device(params, rays, ray_count, capacity);
}

std::optional<double> OptixRayTracer::gpu_ms(rt::GpuTicket ticket, bool wait) {
  return state_->timed.read_ms(ticket, wait);
}

void OptixRayTracer::drop_ticket(rt::GpuTicket ticket) { state_->timed.drop(ticket); }

std::optional<rt::GpuTicket> OptixRayTracer::last_update() { return state_->timed.take_last_update(); }

vec3* OptixRayTracer::device_positions(uint32_t mesh) {
  State& s = *state_;
  s.require_built("device_positions()");
  if (mesh >= s.meshes.size()) fail("rt optix: device_positions of mesh {} of {}", mesh, s.meshes.size());
  return s.meshes[mesh].gas.device_positions();
}

void OptixRayTracer::update_device(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  State& s = *state_;
  s.require_built("update_device()");
  for (const std::uint32_t m : dirty_meshes)
    if (m >= s.meshes.size()) fail("rt optix: dirty mesh {} of {}", m, s.meshes.size());
  const rt::GpuTicket ticket = cuda::start_span(s.timed, s.stream.get());
  s.update_structures(dirty_meshes, policy);
  cuda::stop_span(s.timed, ticket, s.stream.get());
  s.timed.opened_update(ticket);
}

}  // namespace glint::optix
