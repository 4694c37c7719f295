#pragma once
// The embree backend: Embree 3 with instancing. One Embree scene per mesh (one triangle geometry,
// Embree-owned vertex and index buffers, RTC_SCENE_FLAG_ROBUST so that it is watertight like
// glint's own traversal), and a top-level scene of one instance geometry per Scene::instance whose
// geomID is the instance's index, so Embree's instID is hit.instance and its primID hit.prim.
//
// Static meshes are built at RTC_BUILD_QUALITY_MEDIUM. Deformable meshes use Embree's dynamic
// pattern (RTC_SCENE_FLAG_DYNAMIC): update() with policy refit or automatic commits them with
// geometry quality RTC_BUILD_QUALITY_REFIT (Embree refits), with rebuild at
// RTC_BUILD_QUALITY_MEDIUM (Embree builds anew). Embree does not expose its nodes, so automatic
// cannot measure the SAH drift here: it always refits (and stats().blas_sah_drift is absent).
#include "rt/embree/embree_device.h"
#include "rt/ray_tracer.h"
#include "rt/scene_shape.h"

#include <embree3/rtcore.h>

#include <memory>
#include <vector>

namespace glint::rt {

class EmbreeRayTracer final : public RayTracer {
public:
  EmbreeRayTracer();
  ~EmbreeRayTracer() override;
  EmbreeRayTracer(const EmbreeRayTracer&) = delete;
  EmbreeRayTracer& operator=(const EmbreeRayTracer&) = delete;

  void build(const Scene& scene, const AccelOptions& options) override;
  void update(const Scene& scene, std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) override;
  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const override;
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const override;
  RayTracerStats stats() const override;
  std::string_view name() const override { return "embree"; }

private:
  struct MeshScene {
    RTCScene scene = nullptr;
    RTCGeometry geometry = nullptr;  // null for a mesh without triangles (Embree rejects empty buffers)
    vec3* vertices = nullptr;        // Embree-owned vertex buffer of `geometry`
    bool deformable = false;
  };

  void release();
  void require_built(const char* what) const;
  void set_instance_transforms(const Scene& scene);

  // unique_ptr: the device must not move (Embree holds a pointer to it for its callbacks).
  std::unique_ptr<EmbreeDevice> device_;
  SceneShape shape_;
  std::vector<MeshScene> meshes_;
  std::vector<RTCGeometry> instances_;  // one per Scene::instance, geomID = its index
  RTCScene top_ = nullptr;
  double build_ms_ = 0.0;
  double last_update_ms_ = 0.0;
  size_t rebuilds_ = 0;
  size_t refits_ = 0;
};

}  // namespace glint::rt
