#pragma once
// What glint.Structure is on the C++ side: one triangle mesh (a one-mesh, one-instance Scene) in any
// rt::RayTracer backend (cpu, embree, cuda, optix) built with any builder of accel's menu, traced,
// refitted and measured through the RayTracer interface the renderer uses, so Python sees exactly
// the hits the renderer's tracers give. No Python types here: python/module.cpp converts the arrays.
#include "accel/builders/builder.h"
#include "accel/ray.h"
#include "core/math.h"
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace glint::python {

// The backends a Structure can use: those that trace host rays without the renderer's GL context
// (rt::make_ray_tracer knows more, e.g. GL compute tracing, which needs the frame pipeline's context).
inline constexpr const char* kStructureBackends[] = {"cpu", "embree", "cuda", "optix"};

class MeshStructure {
public:
  // `builder`: accel::builder_name of the cpu and cuda backends' BVH (embree and optix build their
  // own: any other name than the default "sah" is a glint::Error there). glint::Error for an unknown
  // builder, a backend not in kStructureBackends or not in this build, a GPU backend without a CUDA
  // GPU, an index out of range, a non-finite vertex or no triangles.
  MeshStructure(std::vector<vec3> positions, std::vector<uint32_t> indices, const std::string& builder,
                const std::string& backend);

  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const;
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const;
  // The vertices moved (same count, same triangles): the structure follows by `policy`.
  // glint::Error for another vertex count, a non-finite vertex, or a refit of a structure that
  // cannot be refitted (sbvh).
  void update(std::vector<vec3> positions, rt::UpdatePolicy policy);

  rt::RayTracerStats stats() const { return tracer_->stats(); }
  const std::string& builder() const { return builder_; }
  const std::string& backend() const { return backend_; }
  std::size_t vertex_count() const { return scene_.meshes[0].positions.size(); }
  std::size_t triangle_count() const { return scene_.meshes[0].triangle_count(); }

private:
  std::string builder_;
  std::string backend_;
  Scene scene_;
  std::unique_ptr<rt::RayTracer> tracer_;
};

}  // namespace glint::python
