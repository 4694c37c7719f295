#pragma once
// The optix backend (docs/optix.md): NVIDIA OptiX's structures behind glint's RayTracer interface,
// the paper's engine in its modern form and the GPU reference glint's own CUDA structures are
// measured against. One GAS per mesh (built over the mesh's own index buffer) and one IAS over the
// scene's instances; the closest-hit and occlusion queries run the device programs of src/optix/device/.
//
// Builder choice: AccelOptions::backend_structure, named in optix/build_preference.h (optix-fasttrace,
// the default: PREFER_FAST_TRACE, static GASes compacted; optix-fastbuild: PREFER_FAST_BUILD). update() with refit or auto updates the
// deformable meshes' GASes in place (OPTIX_BUILD_OPERATION_UPDATE; OptiX reports no quality measure,
// so auto never decides to rebuild), with rebuild builds them again; the IAS is rebuilt every
// update. Deformable meshes' GASes are never compacted (that needs a host wait per rebuild).
//
// Plain C++ (no OptiX or CUDA headers); built only with GLINT_HAVE_OPTIX (backends/registry.cpp makes it).
#include "rt/ray_tracer.h"

#include <memory>
#include <optional>

namespace glint::optix {

class OptixRayTracer final : public rt::RayTracer, public rt::DeviceTracing {
public:
  // Creates the OptiX context and pipeline. glint::Error, one line, without a CUDA GPU or with a
  // driver whose OptiX cannot run these headers.
  OptixRayTracer();
  ~OptixRayTracer() override;

  void build(const Scene& scene, const rt::AccelOptions& options) override;
  // Synchronous: returns when the structures are up to date on the GPU.
  void update(const Scene& scene, std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) override;
  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const override;
  // The same pipeline's occlusion query (terminate on first hit, no hit programs).
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const override;
  // build_ms: wall clock of build() (synchronous); last_update_ms: GPU time (CUDA events) of the last
  // update's structure work, waiting for it when it is still running. Memory: GASes, IAS, instance
  // records and the device copy of the meshes. blas_sah_drift is absent (OptiX hides its nodes).
  rt::RayTracerStats stats() const override;
  std::string_view name() const override { return "optix"; }
  rt::DeviceTracing* device_tracing() override { return this; }

  void* stream() override;
  rt::GpuTicket trace_closest_device(const accel::Ray* rays, accel::Hit* hits, const uint32_t* ray_count,
                                     uint32_t capacity) override;
  rt::GpuTicket trace_any_device(const accel::Ray* rays, uint32_t* occluded, const uint32_t* ray_count,
                                 uint32_t capacity) override;
  std::optional<double> gpu_ms(rt::GpuTicket ticket, bool wait) override;
  void drop_ticket(rt::GpuTicket ticket) override;
  std::optional<rt::GpuTicket> last_update() override;
  vec3* device_positions(uint32_t mesh) override;
  void update_device(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy) override;

private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace glint::optix
