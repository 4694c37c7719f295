#include "rt/cpu_ray_tracer.h"

#include "accel/bvh_stats.h"
#include "accel/kdtree/kdtree_tlas.h"
#include "accel/refit.h"
#include "accel/tlas_trace.h"
#include "accel/wide/wide_bvh_collapse.h"
#include "accel/wide/wide_bvh_refit.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "rt/update_decision.h"
#include "rt/wide_two_level_trace.h"

#include <algorithm>

namespace glint::rt {
namespace {

std::vector<accel::Instance> make_instances(const Scene& scene) {
  std::vector<accel::Instance> instances;
  instances.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) instances.push_back(accel::make_instance(instance.mesh, instance.transform));
  return instances;
}

}  // namespace

accel::TriangleMesh CpuRayTracer::mesh_view(const MeshBlas& mesh) const {
  return accel::make_indexed_mesh(mesh.positions, mesh.indices);
}

void CpuRayTracer::rebuild_blas(uint32_t mesh_index) {
  MeshBlas& mesh = meshes_[mesh_index];
  const accel::TriangleMesh view = mesh_view(mesh);
  if (options_.blas == BlasKind::kdtree) {
    mesh.kdtree = accel::build_kdtree(view);
    kd_blases_[mesh_index] = accel::make_kd_blas(mesh.kdtree, view);
    return;
  }
  mesh.bvh = accel::build_bvh(options_.builder, view, options_.build);
  mesh.sah_at_rebuild = accel::sah_cost(mesh.bvh, options_.build);
  // The new BVH lives in new storage: the traversal's view must follow it.
  blases_[mesh_index] = accel::make_blas(mesh.bvh, view);
  // collapse_to_wide refuses split references (it is checked here rather than caught, so a real
  // collapse error still surfaces): such a mesh keeps tracing its binary BVH.
  mesh.has_wide = options_.wide_traversal && mesh.bvh.refittable;
  mesh.wide = mesh.has_wide ? accel::collapse_to_wide<8>(mesh.bvh, view) : accel::WideBvh8{};
  wide_blases_[mesh_index] = mesh.has_wide ? &mesh.wide : nullptr;
}

void CpuRayTracer::require_built(const char* what) const {
  if (!built_) fail("rt cpu: {} before build()", what);
}

void CpuRayTracer::build(const Scene& scene, const AccelOptions& options) {
  scene.validate();
  if (!(options.auto_rebuild_sah_ratio >= 1.0f))
    fail("rt cpu: auto_rebuild_sah_ratio must be >= 1 (got {})", options.auto_rebuild_sah_ratio);
  const Stopwatch watch;
  built_ = false;
  options_ = options;
  shape_ = scene_shape(scene);
  meshes_.clear();
  meshes_.resize(scene.meshes.size());
  blases_.assign(scene.meshes.size(), accel::Blas{});
  kd_blases_.assign(options.blas == BlasKind::kdtree ? scene.meshes.size() : 0, accel::KdBlas{});
  wide_blases_.assign(scene.meshes.size(), nullptr);
  for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
    meshes_[m].positions = scene.meshes[m].positions;
    meshes_[m].indices = scene.meshes[m].indices;
    meshes_[m].deformable = scene.meshes[m].deformable;
    rebuild_blas(m);
  }
  // The TLAS over the BLASes' root boxes: the BVHs' root nodes, or the kd-trees' root cells.
  tlas_ = options_.blas == BlasKind::kdtree
              ? accel::build_tlas(accel::kd_blas_boxes(kd_blases_), make_instances(scene), accel::BvhBuilder::sah,
                                  options_.build)
              : accel::build_tlas(blases_, make_instances(scene), accel::BvhBuilder::sah, options_.build);
  build_ms_ = watch.elapsed_ms();
  last_update_ms_ = 0.0;
  rebuilds_ = refits_ = 0;
  built_ = true;
}

void CpuRayTracer::update(const Scene& scene, std::span<const uint32_t> dirty_meshes, UpdatePolicy policy) {
  require_built("update()");
  check_update(name(), shape_, scene, dirty_meshes);
  // Checked before anything changes, so a refused update leaves the structures as they were.
  for (uint32_t m : dirty_meshes)
    if (const std::string refusal = update_refusal(name(), policy, options_.structure(), scene.meshes[m].name);
        !refusal.empty())
      fail("{}", refusal);
  const Stopwatch watch;
  for (uint32_t m : dirty_meshes) {
    MeshBlas& mesh = meshes_[m];
    // Same count (checked above), new positions: the views' pointers stay valid.
    std::copy(scene.meshes[m].positions.begin(), scene.meshes[m].positions.end(), mesh.positions.begin());
    // Refit first (the automatic rule measures the refitted BVH). The binary BVH is refitted even
    // when tracing is wide: the TLAS boxes and the SAH drift come from it.
    if (policy != UpdatePolicy::rebuild) accel::refit(mesh.bvh, mesh_view(mesh));
    const std::optional<double> sah_now = policy == UpdatePolicy::automatic
                                              ? std::optional<double>(accel::sah_cost(mesh.bvh, options_.build))
                                              : std::nullopt;
    if (decide_blas_update(policy, sah_now, mesh.sah_at_rebuild, options_.auto_rebuild_sah_ratio) ==
        BlasUpdate::rebuild) {
      rebuild_blas(m);
      ++rebuilds_;
    } else {
      // The wide BVH is refitted in place (re-gather its triangle blocks, boxes bottom-up) rather
      // than collapsed again from the refitted binary BVH: same topology, no allocation, and
      // measured faster (docs/ray-tracer.md).
      if (mesh.has_wide) accel::refit(mesh.wide, mesh_view(mesh));
      ++refits_;
    }
  }
  // Transforms may have moved too (the walkthrough's animated instances): re-read them all, the
  // TLAS is small.
  for (size_t i = 0; i < scene.instances.size(); ++i)
    tlas_.instances[i] = accel::make_instance(scene.instances[i].mesh, scene.instances[i].transform);
  if (options_.blas == BlasKind::kdtree)
    accel::refit_tlas(tlas_, accel::kd_blas_boxes(kd_blases_));
  else
    accel::refit_tlas(tlas_, blases_);
  last_update_ms_ = watch.elapsed_ms();
}

void CpuRayTracer::trace_closest(std::span<const accel::Ray> rays, std::span<accel::Hit> hits) const {
  require_built("trace_closest()");
  if (options_.blas == BlasKind::kdtree)
    accel::trace_closest(tlas_, kd_blases_, rays, hits);
  else if (options_.wide_traversal)
    trace_closest_wide(tlas_, blases_, wide_blases_, rays, hits);
  else
    accel::trace_closest(tlas_, blases_, rays, hits);
}

void CpuRayTracer::trace_any(std::span<const accel::Ray> rays, std::span<uint8_t> occluded) const {
  require_built("trace_any()");
  if (options_.blas == BlasKind::kdtree)
    accel::trace_any(tlas_, kd_blases_, rays, occluded);
  else if (options_.wide_traversal)
    trace_any_wide(tlas_, blases_, wide_blases_, rays, occluded);
  else
    accel::trace_any(tlas_, blases_, rays, occluded);
}

RayTracerStats CpuRayTracer::stats() const {
  RayTracerStats stats;
  stats.backend = std::string(name());
  stats.build_ms = build_ms_;
  stats.last_update_ms = last_update_ms_;
  stats.rebuilds = rebuilds_;
  stats.refits = refits_;
  uint64_t bytes = accel::compute_stats(tlas_.bvh).memory_bytes + tlas_.instances.size() * sizeof(accel::Instance) +
                   blases_.size() * sizeof(accel::Blas);
  for (const MeshBlas& mesh : meshes_) {
    bytes += accel::compute_stats(mesh.bvh).memory_bytes + mesh.positions.size() * sizeof(vec3) +
             mesh.indices.size() * sizeof(uint32_t) + mesh.wide.nodes.size() * sizeof(accel::WideNode<8>) +
             mesh.wide.blocks.size() * sizeof(accel::TriangleBlock<8>) +
             mesh.kdtree.nodes.size() * sizeof(accel::KdNode) + mesh.kdtree.prim_indices.size() * sizeof(uint32_t);
    if (!mesh.deformable || mesh.sah_at_rebuild <= 0.0) continue;
    const double drift = accel::sah_cost(mesh.bvh, options_.build) / mesh.sah_at_rebuild;
    stats.blas_sah_drift = std::max(stats.blas_sah_drift.value_or(0.0), drift);
  }
  stats.memory_bytes = bytes;
  return stats;
}

}  // namespace glint::rt
