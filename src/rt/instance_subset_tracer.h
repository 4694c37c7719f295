#pragma once
// A RayTracer that sees only some instances of a scene: the paper's Fig. 10 ray traces the deforming
// dinosaurs alone, "ignoring all the rest of the scene", to isolate what rebuilding their
// structures costs. It builds any backend (make_ray_tracer's) over a scene holding only the chosen
// instances and the meshes they draw, and answers in the full scene's hit convention (hit.instance
// is the index in the full Scene::instances), so the hit shading pass shades its hits unchanged.
//
// The hits are renumbered on the host, so this tracer exposes no DeviceTracing: with a GPU backend
// the rays and hits travel through host memory (RayTracedReflections' CPU path).
#include "rt/ray_tracer.h"

#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace glint::rt {

// The instances of `scene` whose mesh is deformable, ascending.
std::vector<std::uint32_t> deformable_instances(const Scene& scene);

class InstanceSubsetTracer final : public RayTracer {
public:
  // `instances`: indices into the Scene::instances that build() and update() will be given. An
  // empty list, or one naming an instance twice, is a glint::Error; one out of range is an error
  // at build().
  InstanceSubsetTracer(std::unique_ptr<RayTracer> inner, std::vector<std::uint32_t> instances);

  void build(const Scene& scene, const AccelOptions& options) override;
  // Copies the moved vertices of the dirty meshes that the chosen instances draw (others are
  // ignored) and the chosen instances' transforms, then updates the inner backend.
  void update(const Scene& scene, std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) override;
  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const override;
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const override;
  RayTracerStats stats() const override { return inner_->stats(); }
  std::string_view name() const override { return inner_->name(); }

  // The scene the inner backend was built over (the chosen instances, in the given order).
  const Scene& subset_scene() const { return subset_; }

private:
  std::unique_ptr<RayTracer> inner_;
  std::vector<std::uint32_t> instances_;     // subset instance i is full-scene instance instances_[i]
  std::vector<std::uint32_t> subset_mesh_;   // full-scene mesh -> subset mesh, kNotInSubset if unused
  std::vector<std::uint32_t> full_mesh_;     // subset mesh -> full-scene mesh
  std::vector<std::uint32_t> subset_dirty_;  // reused by update()
  Scene subset_;
};

}  // namespace glint::rt
