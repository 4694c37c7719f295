#pragma once
// The bottom level of a two-level tracer built from glint's own binary BVHs on the CPU, as the gl
// backend keeps it: one BLAS per mesh (AccelOptions::builder over the mesh's object-space triangles,
// in an own copy of its geometry, so the caller's scene may change), and what update() does to a dirty
// mesh by policy: rebuild; refit (accel::refit); or automatic, the cpu backend's rule (refit, then
// rebuild when the SAH cost passed auto_rebuild_sah_ratio x the cost at the last rebuild). The
// counters and the SAH drift are the ones RayTracerStats reports. No GL: the gl backend uploads the
// result (gl_structure_buffers.h).
#include "accel/bvh.h"
#include "accel/tlas.h"
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace glint::gl_rt {

class MeshBlases {
public:
  struct Mesh {
    std::string name;  // the scene mesh's, for messages
    std::vector<vec3> positions;
    std::vector<uint32_t> indices;
    accel::Bvh bvh;
    bool deformable = false;
    double sah_at_rebuild = 0.0;  // SAH cost right after the last (re)build
  };

  // Copies every mesh of `scene` and builds its BVH with options.builder (options as validated by
  // the caller); resets the counters.
  void build(const Scene& scene, const rt::AccelOptions& options);

  // glint::Error naming `backend` when `policy` refits and a dirty mesh's BVH cannot be refitted
  // (sbvh); call it before changing anything, so a refused update leaves the structures as they were.
  void check_refittable(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy,
                        std::string_view backend) const;

  // Copies the dirty meshes' positions from `scene` (checked with rt::check_update and
  // check_refittable) and rebuilds or refits their BVHs by `policy`. Returns, per entry of
  // dirty_meshes, whether that BVH was rebuilt (new primitive order and node count) rather than
  // refitted (same topology, new boxes).
  std::vector<bool> update(const Scene& scene, std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy);

  // A mesh posed on the GPU (the gl backend's update_gl): `positions`, read back from GL, become its
  // positions and its BVH is built again with options.builder, counted as a rebuild.
  void rebuild_at(uint32_t mesh, std::span<const vec3> positions);

  const std::vector<Mesh>& meshes() const { return meshes_; }
  // Views of meshes(), one per mesh: what accel::build_tlas takes.
  std::span<const accel::Blas> blases() const { return blases_; }
  size_t rebuilds() const { return rebuilds_; }
  size_t refits() const { return refits_; }
  // Max over deformable meshes of SAH now / SAH at the last rebuild; nullopt without one. "Now" is
  // `measured[m]` where the caller has it (the GPU's measurement of a BLAS refitted on the GPU, whose
  // host BVH is older) and the host BVH's cost otherwise.
  std::optional<double> sah_drift(std::span<const std::optional<double>> measured = {}) const;

private:
  void rebuild(uint32_t mesh);

  rt::AccelOptions options_;
  std::vector<Mesh> meshes_;
  std::vector<accel::Blas> blases_;
  size_t rebuilds_ = 0;
  size_t refits_ = 0;
};

}  // namespace glint::gl_rt
