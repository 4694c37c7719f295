#pragma once
// The cpu backend: glint's own two-level structure (accel/tlas.h). One BLAS per mesh, built with
// AccelOptions::builder over the mesh's object-space triangles, a binned-SAH TLAS over
// Scene::instances, traced with accel's TBB batch (accel/tlas_trace.h). trace_any walks the same
// structures in accel's any-hit mode (traverse_bvh<true>), ending each ray at its first hit.
//
// update(): every dirty mesh's BLAS is rebuilt (rebuild), refitted (refit; a glint::Error for a
// builder whose BVHs cannot be refitted, e.g. sbvh), or, for automatic, refitted and then rebuilt
// when its SAH cost (accel::compute_stats) exceeds auto_rebuild_sah_ratio x its SAH cost at its
// last (re)build. Then the TLAS is refitted over the new BLAS boxes and the current transforms.
//
// AccelOptions::blas = kdtree: an SAH kd-tree per mesh instead (accel/kdtree/kdtree_tlas.h: the same TLAS over
// the trees' root cells, each instance's kd-tree walked front to back); updates rebuild it (refit and
// automatic are refused, as for sbvh: rt/update_decision.h). wide_traversal does not apply.
//
// Tracing (AccelOptions::wide_traversal, the default): every BLAS is also collapsed to an 8-wide
// BVH (accel/wide/wide_bvh_collapse.h) after each (re)build and refitted with it, and the TLAS walk
// enters those with the SIMD kernel (rt/wide_two_level_trace.h). The binary BVH stays the master:
// the TLAS boxes, the automatic policy's SAH cost and the drift in stats() come from it. A builder
// whose BVH cannot be collapsed (sbvh, split references) traces its binary BVH for that mesh.
#include "accel/bvh.h"
#include "accel/kdtree/kdtree_tlas.h"
#include "accel/tlas.h"
#include "accel/wide/wide_bvh.h"
#include "rt/ray_tracer.h"
#include "rt/scene_shape.h"

#include <vector>

namespace glint::rt {

class CpuRayTracer final : public RayTracer {
public:
  void build(const Scene& scene, const AccelOptions& options) override;
  void update(const Scene& scene, std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) override;
  void trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const override;
  void trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const override;
  RayTracerStats stats() const override;
  std::string_view name() const override { return "cpu"; }

private:
  // One mesh's own copy of its geometry (the BLAS views point into it, so the caller's scene may
  // change) and its BVH.
  struct MeshBlas {
    std::vector<vec3> positions;
    std::vector<uint32_t> indices;
    accel::Bvh bvh;        // empty with BlasKind::kdtree
    accel::KdTree kdtree;  // BlasKind::kdtree only
    accel::WideBvh8 wide;  // collapsed from bvh; empty unless has_wide
    bool has_wide = false;
    bool deformable = false;
    double sah_at_rebuild = 0.0;  // SAH cost right after the last (re)build
  };

  accel::TriangleMesh mesh_view(const MeshBlas& mesh) const;
  void rebuild_blas(uint32_t mesh_index);
  void require_built(const char* what) const;

  AccelOptions options_;
  SceneShape shape_;
  std::vector<MeshBlas> meshes_;
  std::vector<accel::Blas> blases_;  // views of meshes_, one per mesh, rebuilt with the BVHs
  // &meshes_[m].wide when it has one, else nullptr (trace the binary BVH); meshes_ never moves
  // after build(), so the pointers stay valid.
  std::vector<const accel::WideBvh8*> wide_blases_;
  std::vector<accel::KdBlas> kd_blases_;  // views of meshes_' kd-trees (BlasKind::kdtree), else empty
  accel::Tlas tlas_;
  bool built_ = false;
  double build_ms_ = 0.0;
  double last_update_ms_ = 0.0;
  size_t rebuilds_ = 0;
  size_t refits_ = 0;
};

}  // namespace glint::rt
