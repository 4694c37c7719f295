#include "cuda/cuda_ray_tracer.h"

#include "accel/bvh_stats.h"
#include "core/stopwatch.h"
#include "cuda/cuda_check.h"
#include "cuda/cuda_span.h"
#include "cuda/cuda_stream_events.h"
#include "cuda/device_query.h"
#include "cuda/gpu_bvh_build.h"
#include "cuda/gpu_bvh_sah.h"
#include "cuda/gpu_kdtree.h"
#include "cuda/gpu_mesh.h"
#include "cuda/gpu_trace.h"
#include "cuda/pinned_upload.h"
#include "cuda/tracer_gpu_times.h"
#include "rt/scene_shape.h"
#include "rt/update_decision.h"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace glint::cuda {
namespace {

bool builds_on_gpu(accel::BvhBuilder builder) {
  return builder == accel::BvhBuilder::lbvh || builder == accel::BvhBuilder::ploc;
}

GpuBvhBuilder gpu_builder_of(accel::BvhBuilder builder) {
  return builder == accel::BvhBuilder::ploc ? GpuBvhBuilder::ploc : GpuBvhBuilder::lbvh;
}

// Host memory the GPU copies small results into (page-locked, so the copy is truly asynchronous).
template <typename T>
class PinnedArray {
public:
  PinnedArray() = default;
  ~PinnedArray() {
    if (data_) cudaFreeHost(data_);
  }
  PinnedArray(const PinnedArray&) = delete;
  PinnedArray& operator=(const PinnedArray&) = delete;

  void reset(std::size_t count) {
    if (data_) cudaFreeHost(data_);
    data_ = nullptr;
    if (count != 0) GLINT_CUDA_CHECK(cudaMallocHost(reinterpret_cast<void**>(&data_), count * sizeof(T)));
    std::fill(data_, data_ + count, T{});
  }
  T* data() { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }

private:
  T* data_ = nullptr;
};

// A timed device-side trace or update: its events, and its traversal stack overflow word, zeroed
// before the work, set by a trace, and copied behind it to pinned host memory for gpu_ms to check
// once the GPU is past the span (the pool reuses a span only after it was read or let go, and one
// stream orders the reuse after the work).
struct TracedSpan : CudaSpan {
  TracedSpan() : device_overflow(1) { host_overflow.reset(1); }
  DeviceBuffer<uint32_t> device_overflow;
  PinnedArray<uint32_t> host_overflow;
};

class CudaRayTracer final : public rt::RayTracer, public rt::DeviceTracing {
public:
  // make_cuda_ray_tracer checks for a GPU first (the members' CUDA stream and events need one).
  explicit CudaRayTracer(const CudaTracerOptions& tracer_options) : tracer_options_(tracer_options) {}
  // Work still queued uses the buffers, which go before the stream does.
  ~CudaRayTracer() override { cudaStreamSynchronize(stream_.get()); }

  void build(const Scene& scene, const rt::AccelOptions& options) override;
  void update(const Scene& scene, std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) override;
  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const override;
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const override;
  rt::RayTracerStats stats() const override;
  std::string_view name() const override { return "cuda"; }
  rt::DeviceTracing* device_tracing() override { return this; }

  void* stream() override { return stream_.get(); }
  rt::GpuTicket trace_closest_device(const accel::Ray* rays, accel::Hit* hits, const uint32_t* ray_count,
                                     uint32_t capacity) override;
  rt::GpuTicket trace_any_device(const accel::Ray* rays, uint32_t* occluded, const uint32_t* ray_count,
                                 uint32_t capacity) override;
  bool traces_hit_shadows() const override { return true; }
  rt::HitAndShadowTickets trace_closest_and_hit_shadows_device(const accel::Ray* rays, accel::Hit* hits,
                                                               const uint32_t* ray_count, uint32_t capacity,
                                                               const rt::HitShadowRays& shadows) override;
  std::optional<double> gpu_ms(rt::GpuTicket ticket, bool wait) override;
  void drop_ticket(rt::GpuTicket ticket) override { timed_.drop(ticket); }
  std::optional<rt::GpuTicket> last_update() override { return timed_.take_last_update(); }
  vec3* device_positions(uint32_t mesh) override;
  void update_device(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) override;

private:
  struct MeshState {
    GpuMesh mesh;
    // Host copies for the CPU builders (rebuilds read them); the positions are stale after a GPU
    // deformation until read back.
    std::vector<vec3> host_positions;
    std::vector<uint32_t> host_indices;
    bool host_positions_current = true;
    bool deformable = false;
    DeviceBuffer<Aabb> boxes;  // triangle boxes: the GPU builders' input (a refit reads the triangles)
    GpuBvh bvh;          // empty with BlasKind::kdtree
    GpuKdTree kdtree;    // BlasKind::kdtree only: built on the CPU, uploaded
    std::optional<GpuBvhBuild> gpu_builder;
    DeviceBuffer<uint32_t> refit_counters;
    DeviceBuffer<double> sah_sums;
  };

  void require_built(const char* what) const;
  void require_refittable(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) const;
  void rebuild_mesh(uint32_t m);
  // CPU builders (and the kd-tree) build from host positions: after a GPU deformation, read them back.
  void read_back_host_positions(MeshState& state);
  // The BLASes of `refitted` in one launch (refit_meshes_gpu); measure_sah: also measure their SAH
  // costs now (the automatic policy reads them at the next update).
  void refit_meshes(std::span<const uint32_t> refitted, bool measure_sah);
  void upload_blas_views();
  // instance_boxes_ from the BLASes' root boxes (BVH roots or kd-tree cells) and the transforms.
  void launch_instance_boxes();
  // The update of the dirty meshes' BLASes and the TLAS, timed (the last update of timed_).
  void update_structures(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy);
  void enqueue_update(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy);
  accel::TlasView tlas_view() const {
    return {tlas_.view(), instances_.device(), blas_views_.device()};
  }
  bool kdtree() const { return options_.blas == rt::BlasKind::kdtree; }
  // Calls launch(view) with the TLAS view of this structure's kind: accel::TlasView (BVH BLASes) or
  // accel::KdTlasView (kd-tree BLASes), whose launches are overloads of the same names.
  template <typename Launch>
  void with_tlas_view(Launch&& launch) const {
    if (kdtree())
      launch(accel::KdTlasView{tlas_.view(), instances_.device(), kd_blas_views_.device()});
    else
      launch(tlas_view());
  }
  // Host-side traces: waits for the trace and throws when its traversal stack overflowed.
  void check_overflow() const;
  // Either output (hits: closest hit; occluded: any hit), the other null; `overflow`: a device word
  // zeroed before the launch.
  TraceLaunch trace_launch(const accel::Ray* rays, accel::Hit* hits, uint32_t* occluded, const uint32_t* ray_count,
                           uint32_t capacity, uint32_t* overflow) const {
    TraceLaunch launch{rays, hits, ray_count, capacity, overflow, next_ray_.data(), tracer_options_.trace_kernel};
    launch.occluded = occluded;
    return launch;
  }
  // Enqueued GPU work between the events of a new span, given the span's zeroed overflow word
  // (TracedSpan).
  template <typename Work>
  rt::GpuTicket timed(Work&& work);
  // Uploads host rays for trace_closest / trace_any (checked: as many as `results`, fewer than 2^32).
  uint32_t upload_host_rays(std::span<const accel::Ray> rays, std::size_t results, const char* result_name) const;

  // Every call enqueues here; non-blocking, so the legacy default stream does not order it.
  CudaStream stream_{cudaStreamNonBlocking};
  rt::AccelOptions options_;
  CudaTracerOptions tracer_options_;
  rt::SceneShape shape_;
  std::vector<std::string> mesh_names_;
  std::vector<MeshState> meshes_;
  std::vector<MeshRefit> mesh_refits_;  // refit_meshes' list, kept so a deforming frame allocates nothing
  std::vector<accel::Instance> host_instances_;
  // Small per-update uploads through pinned memory, so enqueuing them never waits for the GPU.
  PinnedUpload<accel::Instance> instances_;
  PinnedUpload<accel::Blas> blas_views_;
  PinnedUpload<accel::KdBlas> kd_blas_views_;  // BlasKind::kdtree: the meshes' kd-tree views
  DeviceBuffer<Aabb> instance_boxes_;
  GpuBvh tlas_;
  std::optional<GpuBvhBuild> tlas_builder_;
  DeviceBuffer<uint32_t> tlas_refit_counters_;

  // SAH cost per mesh, [2m] at its last rebuild and [2m + 1] after its last refit, computed on the GPU:
  // at every (re)build; after a refit only for the automatic policy, whose updates copy them to
  // pinned host memory (sah_ready_) for the next update to read; stats() measures the current cost.
  mutable DeviceBuffer<float> device_sah_;
  mutable DeviceBuffer<double> stats_sah_sums_;
  mutable PinnedArray<float> host_sah_;
  CudaEvent sah_ready_;
  bool sah_copied_ = false;

  // Host-side tracing: the rays and hits in device memory (kept, so repeated calls allocate nothing).
  mutable DeviceBuffer<accel::Ray> host_rays_;
  mutable DeviceBuffer<accel::Hit> host_hits_;
  mutable DeviceBuffer<uint32_t> host_occluded_;
  mutable std::vector<uint32_t> host_occluded_download_;
  // The traversal stack overflow flag of host-side traces (device-side ones have their span's).
  mutable DeviceBuffer<uint32_t> host_trace_overflow_;
  mutable DeviceBuffer<uint32_t> next_ray_;  // the persistent kernel's ray counter
  // Device-side traces and structure updates, timed for gpu_ms; stats() reads the last update's time.
  mutable TracerGpuTimes<TracedSpan> timed_{"rt cuda"};

  bool built_ = false;
  double build_ms_ = 0.0;
  std::size_t rebuilds_ = 0;
  std::size_t refits_ = 0;
};

void CudaRayTracer::require_built(const char* what) const {
  if (!built_) fail_message(std::string("rt cuda: ") + what + " before build()");
}

void CudaRayTracer::require_refittable(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) const {
  for (uint32_t m : dirty_meshes)
    if (const std::string refusal = rt::update_refusal(name(), policy, options_.structure(), mesh_names_[m]);
        !refusal.empty())
      fail_message(refusal);
}

void CudaRayTracer::rebuild_mesh(uint32_t m) {
  MeshState& state = meshes_[m];
  const uint32_t triangles = state.mesh.triangle_count();
  if (kdtree()) {
    read_back_host_positions(state);
    state.kdtree.upload(accel::build_kdtree(accel::make_indexed_mesh(state.host_positions, state.host_indices)),
                        stream_.get());
    return;  // no BVH SAH to measure: a kd-tree is never refitted
  }
  if (state.gpu_builder) {
    state.boxes.resize(triangles);
    compute_triangle_boxes(state.mesh.view(), state.boxes.data(), stream_.get());
    state.gpu_builder->build(state.boxes.data(), triangles, state.bvh, stream_.get());
  } else {
    read_back_host_positions(state);
    const accel::Bvh host_bvh = accel::build_bvh(
        options_.builder, accel::make_indexed_mesh(state.host_positions, state.host_indices), options_.build);
    state.bvh.upload(host_bvh, stream_.get());
  }
  const accel::SahCosts costs{options_.build.traversal_cost, options_.build.intersection_cost};
  compute_sah_gpu(state.bvh, costs, state.sah_sums, device_sah_.data() + 2 * m, stream_.get());
  GLINT_CUDA_CHECK(cudaMemcpyAsync(device_sah_.data() + 2 * m + 1, device_sah_.data() + 2 * m, sizeof(float),
                                   cudaMemcpyDeviceToDevice, stream_.get()));
}

void CudaRayTracer::read_back_host_positions(MeshState& state) {
  if (state.host_positions_current) return;
  // A GPU deformer moved the vertices: the CPU builder needs them on the host.
  GLINT_CUDA_CHECK(cudaMemcpyAsync(state.host_positions.data(), state.mesh.positions.data(),
                                   state.mesh.positions.bytes(), cudaMemcpyDeviceToHost, stream_.get()));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream_.get()));
  state.host_positions_current = true;
}

void CudaRayTracer::refit_meshes(std::span<const uint32_t> refitted, bool measure_sah) {
  mesh_refits_.clear();
  for (uint32_t m : refitted)
    mesh_refits_.push_back({&meshes_[m].bvh, meshes_[m].mesh.view(), &meshes_[m].refit_counters});
  refit_meshes_gpu(mesh_refits_, stream_.get());
  if (!measure_sah) return;
  const accel::SahCosts costs{options_.build.traversal_cost, options_.build.intersection_cost};
  for (uint32_t m : refitted)
    compute_sah_gpu(meshes_[m].bvh, costs, meshes_[m].sah_sums, device_sah_.data() + 2 * m + 1, stream_.get());
}

// The traversal reads each BLAS through a device array of views; a rebuild may move a BVH's
// storage (a larger CPU-built BVH), so the views are written again after rebuilds.
void CudaRayTracer::upload_blas_views() {
  if (kdtree()) {
    std::vector<accel::KdBlas> views(meshes_.size());
    for (std::size_t m = 0; m < meshes_.size(); ++m) views[m] = {meshes_[m].kdtree.view(), meshes_[m].mesh.view()};
    kd_blas_views_.upload(std::span<const accel::KdBlas>(views), stream_.get());
    return;
  }
  std::vector<accel::Blas> views(meshes_.size());
  for (std::size_t m = 0; m < meshes_.size(); ++m) views[m] = {meshes_[m].bvh.view(), meshes_[m].mesh.view()};
  blas_views_.upload(std::span<const accel::Blas>(views), stream_.get());
}

void CudaRayTracer::build(const Scene& scene, const rt::AccelOptions& options) {
  scene.validate();
  if (!(options.auto_rebuild_sah_ratio >= 1.0f))
    fail_message("rt cuda: auto_rebuild_sah_ratio must be >= 1 (got " + std::to_string(options.auto_rebuild_sah_ratio) +
                 ")");
  const Stopwatch watch;
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream_.get()));
  built_ = false;
  options_ = options;
  shape_ = rt::scene_shape(scene);
  mesh_names_.clear();
  meshes_.clear();
  meshes_.resize(scene.meshes.size());
  device_sah_.resize(2 * scene.meshes.size());
  host_sah_.reset(2 * scene.meshes.size());
  sah_copied_ = false;
  for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    MeshState& state = meshes_[m];
    mesh_names_.push_back(mesh.name);
    state.deformable = mesh.deformable;
    state.mesh.upload(accel::make_indexed_mesh(mesh.positions, mesh.indices), stream_.get());
    if (!kdtree() && builds_on_gpu(options_.builder)) {
      state.gpu_builder.emplace(gpu_builder_of(options_.builder), options_.build);
    } else {
      state.host_positions = mesh.positions;
      state.host_indices = mesh.indices;
    }
    rebuild_mesh(m);
  }
  upload_blas_views();
  host_instances_.clear();
  for (const Instance& instance : scene.instances)
    host_instances_.push_back(accel::make_instance(instance.mesh, instance.transform));
  instances_.upload(std::span<const accel::Instance>(host_instances_), stream_.get());
  instance_boxes_.resize(host_instances_.size());
  launch_instance_boxes();
  tlas_builder_.emplace(GpuBvhBuilder::lbvh, options_.build);
  tlas_builder_->build(instance_boxes_.data(), static_cast<uint32_t>(host_instances_.size()), tlas_, stream_.get());
  host_trace_overflow_.resize(1);
  host_trace_overflow_.fill_zero(stream_.get());
  next_ray_.resize(1);
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream_.get()));
  build_ms_ = watch.elapsed_ms();
  timed_.forget_update();
  rebuilds_ = refits_ = 0;
  built_ = true;
}

void CudaRayTracer::launch_instance_boxes() {
  const auto count = static_cast<uint32_t>(host_instances_.size());
  if (kdtree())
    launch_instance_world_boxes(instances_.device(), count, kd_blas_views_.device(), instance_boxes_.data(), stream_.get());
  else
    launch_instance_world_boxes(instances_.device(), count, blas_views_.device(), instance_boxes_.data(), stream_.get());
}

void CudaRayTracer::update_structures(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  timed_.opened_update(timed([&](uint32_t*) { enqueue_update(dirty_meshes, policy); }));
}

void CudaRayTracer::enqueue_update(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  bool rebuilt_any = false;
  // Automatic: last update's SAH costs are in host memory by now (the copy was queued a frame ago),
  // so waiting for them costs nothing in a frame loop.
  if (policy == rt::UpdatePolicy::automatic && sah_copied_) GLINT_CUDA_CHECK(cudaEventSynchronize(sah_ready_.get()));
  std::vector<uint32_t> refitted;
  for (uint32_t m : dirty_meshes) {
    // The shared rule (rt/update_decision.h), with the SAH cost of the previous update's refit.
    const std::optional<double> sah_after_refit =
        sah_copied_ ? std::optional<double>(host_sah_[2 * m + 1]) : std::nullopt;
    if (rt::decide_blas_update(policy, sah_after_refit, host_sah_[2 * m], options_.auto_rebuild_sah_ratio) ==
        rt::BlasUpdate::rebuild) {
      rebuild_mesh(m);
      rebuilt_any = true;
      ++rebuilds_;
    } else {
      refitted.push_back(m);
      ++refits_;
    }
  }
  if (!refitted.empty()) refit_meshes(refitted, policy == rt::UpdatePolicy::automatic);
  if (rebuilt_any) upload_blas_views();
  launch_instance_boxes();
  if (policy == rt::UpdatePolicy::rebuild)
    tlas_builder_->build(instance_boxes_.data(), static_cast<uint32_t>(host_instances_.size()), tlas_, stream_.get());
  else
    refit_gpu(tlas_, instance_boxes_.data(), tlas_refit_counters_, stream_.get());
  if (policy == rt::UpdatePolicy::automatic) {
    GLINT_CUDA_CHECK(cudaMemcpyAsync(host_sah_.data(), device_sah_.data(), device_sah_.bytes(),
                                     cudaMemcpyDeviceToHost, stream_.get()));
    sah_ready_.record(stream_.get());
    sah_copied_ = true;
  }
}

void CudaRayTracer::update(const Scene& scene, std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  require_built("update()");
  rt::check_update(name(), shape_, scene, dirty_meshes);
  require_refittable(dirty_meshes, policy);
  for (uint32_t m : dirty_meshes) {
    MeshState& state = meshes_[m];
    const std::vector<vec3>& positions = scene.meshes[m].positions;
    state.mesh.positions.upload(std::span<const vec3>(positions), stream_.get());
    if (!state.gpu_builder) {
      std::copy(positions.begin(), positions.end(), state.host_positions.begin());
      state.host_positions_current = true;
    }
  }
  // Transforms may have moved too: re-read them all, the instance list is small.
  for (std::size_t i = 0; i < scene.instances.size(); ++i)
    host_instances_[i] = accel::make_instance(scene.instances[i].mesh, scene.instances[i].transform);
  instances_.upload(std::span<const accel::Instance>(host_instances_), stream_.get());
  update_structures(dirty_meshes, policy);
}

void CudaRayTracer::update_device(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) {
  require_built("update_device()");
  for (uint32_t m : dirty_meshes)
    if (m >= meshes_.size())
      fail_message("rt cuda: dirty mesh index " + std::to_string(m) + " out of range (" +
                   std::to_string(meshes_.size()) + " meshes)");
  require_refittable(dirty_meshes, policy);
  update_structures(dirty_meshes, policy);
}

vec3* CudaRayTracer::device_positions(uint32_t mesh) {
  require_built("device_positions()");
  if (mesh >= meshes_.size())
    fail_message("rt cuda: mesh index " + std::to_string(mesh) + " out of range (" + std::to_string(meshes_.size()) +
                 " meshes)");
  // The caller writes them on the GPU: a CPU builder must read them back before its next rebuild.
  if (!meshes_[mesh].gpu_builder) meshes_[mesh].host_positions_current = false;
  return meshes_[mesh].mesh.positions.data();
}

namespace {

[[noreturn]] void fail_overflow(accel::BvhBuilder builder) {
  fail_message("rt cuda: a traversal stack overflowed (a BVH deeper than " + std::to_string(accel::kMaxBvhDepth) +
                 " levels, from the " + std::string(accel::builder_name(builder)) +
                 " builder); its hits are wrong: use another builder");
}

}  // namespace

void CudaRayTracer::check_overflow() const {
  uint32_t overflowed = 0;
  GLINT_CUDA_CHECK(cudaMemcpyAsync(&overflowed, host_trace_overflow_.data(), sizeof(uint32_t), cudaMemcpyDeviceToHost,
                                   stream_.get()));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream_.get()));
  if (overflowed) fail_overflow(options_.builder);
}

uint32_t CudaRayTracer::upload_host_rays(std::span<const accel::Ray> rays, std::size_t results,
                                         const char* result_name) const {
  if (rays.size() != results)
    fail_message("rt cuda: " + std::to_string(rays.size()) + " rays but " + std::to_string(results) + " " + result_name);
  if (rays.size() > 0xFFFFFFFFu) fail_message("rt cuda: more than 2^32 - 1 rays in one call");
  if (!rays.empty()) host_rays_.upload(rays, stream_.get());
  return static_cast<uint32_t>(rays.size());
}

void CudaRayTracer::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const {
  require_built("trace_closest()");
  const uint32_t count = upload_host_rays(rays, hits.size(), "hits");
  if (count == 0) return;
  host_hits_.resize(count);
  uint32_t* overflow = host_trace_overflow_.data();
  GLINT_CUDA_CHECK(cudaMemsetAsync(overflow, 0, sizeof(uint32_t), stream_.get()));
  with_tlas_view([&](const auto& tlas) {
    launch_trace_closest(tlas, trace_launch(host_rays_.data(), host_hits_.data(), nullptr, nullptr, count, overflow),
                         stream_.get());
  });
  GLINT_CUDA_CHECK(
      cudaMemcpyAsync(hits.data(), host_hits_.data(), hits.size_bytes(), cudaMemcpyDeviceToHost, stream_.get()));
  check_overflow();
}

void CudaRayTracer::trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const {
  require_built("trace_any()");
  const uint32_t count = upload_host_rays(rays, occluded.size(), "occlusion results");
  if (count == 0) return;
  host_occluded_.resize(count);
  host_occluded_download_.resize(count);
  uint32_t* overflow = host_trace_overflow_.data();
  GLINT_CUDA_CHECK(cudaMemsetAsync(overflow, 0, sizeof(uint32_t), stream_.get()));
  with_tlas_view([&](const auto& tlas) {
    launch_trace_any(tlas, trace_launch(host_rays_.data(), nullptr, host_occluded_.data(), nullptr, count, overflow),
                     stream_.get());
  });
  GLINT_CUDA_CHECK(cudaMemcpyAsync(host_occluded_download_.data(), host_occluded_.data(), count * sizeof(uint32_t),
                                   cudaMemcpyDeviceToHost, stream_.get()));
  check_overflow();  // waits for the copy
  // The device side writes one uint32_t per ray (what GLSL reads); the host interface has one byte.
  std::transform(host_occluded_download_.begin(), host_occluded_download_.end(), occluded.begin(),
                 [](uint32_t value) { return static_cast<uint8_t>(value != 0 ? 1 : 0); });
}

template <typename Work>
rt::GpuTicket CudaRayTracer::timed(Work&& work) {
  const rt::GpuTicket ticket = start_span(timed_, stream_.get());
  TracedSpan& span = timed_.span(ticket);
  GLINT_CUDA_CHECK(cudaMemsetAsync(span.device_overflow.data(), 0, sizeof(uint32_t), stream_.get()));
  work(span.device_overflow.data());
  GLINT_CUDA_CHECK(cudaMemcpyAsync(span.host_overflow.data(), span.device_overflow.data(), sizeof(uint32_t),
                                   cudaMemcpyDeviceToHost, stream_.get()));
  stop_span(timed_, ticket, stream_.get());
  return ticket;
}

rt::GpuTicket CudaRayTracer::trace_closest_device(const accel::Ray* rays, accel::Hit* hits, const uint32_t* ray_count,
                                                  uint32_t capacity) {
  require_built("trace_closest_device()");
  return timed([&](uint32_t* overflow) {
    with_tlas_view([&](const auto& tlas) {
      launch_trace_closest(tlas, trace_launch(rays, hits, nullptr, ray_count, capacity, overflow), stream_.get());
    });
  });
}

rt::GpuTicket CudaRayTracer::trace_any_device(const accel::Ray* rays, uint32_t* occluded, const uint32_t* ray_count,
                                              uint32_t capacity) {
  require_built("trace_any_device()");
  return timed([&](uint32_t* overflow) {
    with_tlas_view([&](const auto& tlas) {
      launch_trace_any(tlas, trace_launch(rays, nullptr, occluded, ray_count, capacity, overflow), stream_.get());
    });
  });
}

rt::HitAndShadowTickets CudaRayTracer::trace_closest_and_hit_shadows_device(const accel::Ray* rays, accel::Hit* hits,
                                                                            const uint32_t* ray_count,
                                                                            uint32_t capacity,
                                                                            const rt::HitShadowRays& shadows) {
  require_built("trace_closest_and_hit_shadows_device()");
  if (shadows.shadow_rays == nullptr || shadows.occluded == nullptr)
    fail_message("rt cuda: the hits' shadow rays need device memory for the rays and their answers");
  rt::HitAndShadowTickets tickets;
  tickets.closest = trace_closest_device(rays, hits, ray_count, capacity);
  tickets.shadows = timed([&](uint32_t* overflow) {
    with_tlas_view([&](const auto& tlas) {
      launch_hit_shadow_rays(tlas, rays, hits, ray_count, capacity, shadows.light_position, shadows.origin_offset,
                             shadows.shadow_rays, stream_.get());
      launch_trace_any(tlas, trace_launch(shadows.shadow_rays, nullptr, shadows.occluded, ray_count, capacity, overflow),
                       stream_.get());
    });
  });
  return tickets;
}

std::optional<double> CudaRayTracer::gpu_ms(rt::GpuTicket ticket, bool wait) {
  return timed_.read_ms(ticket, wait, [&](TracedSpan& span) {
    if (span.host_overflow[0] != 0) fail_overflow(options_.builder);
  });
}

rt::RayTracerStats CudaRayTracer::stats() const {
  rt::RayTracerStats stats;
  stats.backend = std::string(name());
  stats.build_ms = build_ms_;
  stats.last_update_ms = timed_.last_update_ms();
  stats.rebuilds = rebuilds_;
  stats.refits = refits_;
  if (!built_) return stats;
  // The deformable meshes' SAH cost now (refits measure it only for the automatic policy), next to
  // their cost at the last rebuild.
  const accel::SahCosts costs{options_.build.traversal_cost, options_.build.intersection_cost};
  // A kd-tree has no BVH SAH: no drift.
  for (uint32_t m = 0; m < meshes_.size(); ++m)
    if (meshes_[m].deformable && !kdtree())
      compute_sah_gpu(meshes_[m].bvh, costs, stats_sah_sums_, device_sah_.data() + 2 * m + 1, stream_.get());
  GLINT_CUDA_CHECK(cudaMemcpyAsync(host_sah_.data(), device_sah_.data(), device_sah_.bytes(), cudaMemcpyDeviceToHost,
                                   stream_.get()));
  GLINT_CUDA_CHECK(cudaStreamSynchronize(stream_.get()));
  uint64_t bytes = tlas_.memory_bytes() + instances_.size() * sizeof(accel::Instance) +
                   blas_views_.size() * sizeof(accel::Blas) + kd_blas_views_.size() * sizeof(accel::KdBlas) +
                   instance_boxes_.bytes();
  for (uint32_t m = 0; m < meshes_.size(); ++m) {
    const MeshState& state = meshes_[m];
    bytes += state.bvh.memory_bytes() + state.kdtree.memory_bytes() + state.mesh.positions.bytes() +
             state.mesh.indices.bytes();
    if (kdtree() || !state.deformable || host_sah_[2 * m] <= 0.0f) continue;
    const double drift = static_cast<double>(host_sah_[2 * m + 1]) / static_cast<double>(host_sah_[2 * m]);
    stats.blas_sah_drift = std::max(stats.blas_sah_drift.value_or(0.0), drift);
  }
  stats.memory_bytes = bytes;
  return stats;
}

}  // namespace

std::unique_ptr<rt::RayTracer> make_cuda_ray_tracer(const CudaTracerOptions& options) {
  require_cuda_gpu("--backend cuda");
  return std::make_unique<CudaRayTracer>(options);
}

}  // namespace glint::cuda
