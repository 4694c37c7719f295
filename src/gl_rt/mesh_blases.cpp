#include "gl_rt/mesh_blases.h"

#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/refit.h"
#include "core/error.h"
#include "rt/update_decision.h"

#include <algorithm>

namespace glint::gl_rt {
namespace {

accel::TriangleMesh mesh_view(const MeshBlases::Mesh& mesh) {
  return accel::make_indexed_mesh(mesh.positions, mesh.indices);
}

}  // namespace

void MeshBlases::rebuild(uint32_t mesh_index) {
  Mesh& mesh = meshes_[mesh_index];
  const accel::TriangleMesh view = mesh_view(mesh);
  mesh.bvh = accel::build_bvh(options_.builder, view, options_.build);
  mesh.sah_at_rebuild = accel::sah_cost(mesh.bvh, options_.build);
  // The new BVH lives in new storage: the view must follow it.
  blases_[mesh_index] = accel::make_blas(mesh.bvh, view);
}

void MeshBlases::build(const Scene& scene, const rt::AccelOptions& options) {
  options_ = options;
  meshes_.clear();
  meshes_.resize(scene.meshes.size());
  blases_.assign(scene.meshes.size(), accel::Blas{});
  for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
    meshes_[m].name = scene.meshes[m].name;
    meshes_[m].positions = scene.meshes[m].positions;
    meshes_[m].indices = scene.meshes[m].indices;
    meshes_[m].deformable = scene.meshes[m].deformable;
    rebuild(m);
  }
  rebuilds_ = refits_ = 0;
}

void MeshBlases::check_refittable(std::span<const uint32_t> dirty_meshes, rt::UpdatePolicy policy,
                                  std::string_view backend) const {
  for (uint32_t m : dirty_meshes)
    if (const std::string refusal = rt::update_refusal(backend, policy, options_.structure(), meshes_[m].name);
        !refusal.empty())
      fail("{}", refusal);
}

std::vector<bool> MeshBlases::update(const Scene& scene, std::span<const uint32_t> dirty_meshes,
                                     rt::UpdatePolicy policy) {
  std::vector<bool> rebuilt;
  rebuilt.reserve(dirty_meshes.size());
  for (uint32_t m : dirty_meshes) {
    Mesh& mesh = meshes_[m];
    // Same count (checked by the caller), new positions: the views' pointers stay valid.
    std::copy(scene.meshes[m].positions.begin(), scene.meshes[m].positions.end(), mesh.positions.begin());
    // The shared rule (rt/update_decision.h): automatic refits first and measures the refitted cost.
    if (policy != rt::UpdatePolicy::rebuild) accel::refit(mesh.bvh, mesh_view(mesh));
    const std::optional<double> sah_now = policy == rt::UpdatePolicy::automatic
                                              ? std::optional<double>(accel::sah_cost(mesh.bvh, options_.build))
                                              : std::nullopt;
    const bool rebuild_it = rt::decide_blas_update(policy, sah_now, mesh.sah_at_rebuild,
                                                   options_.auto_rebuild_sah_ratio) == rt::BlasUpdate::rebuild;
    // The counters record the final action: a refit followed by a rebuild is a rebuild.
    if (rebuild_it) {
      rebuild(m);
      ++rebuilds_;
    } else {
      ++refits_;
    }
    rebuilt.push_back(rebuild_it);
  }
  return rebuilt;
}

void MeshBlases::rebuild_at(uint32_t mesh, std::span<const vec3> positions) {
  if (positions.size() != meshes_[mesh].positions.size())
    fail("rt gl: mesh '{}' has {} vertices, {} given", meshes_[mesh].name, meshes_[mesh].positions.size(),
         positions.size());
  // Same count, new positions: the views' pointers stay valid.
  std::copy(positions.begin(), positions.end(), meshes_[mesh].positions.begin());
  rebuild(mesh);
  ++rebuilds_;
}

std::optional<double> MeshBlases::sah_drift(std::span<const std::optional<double>> measured) const {
  std::optional<double> drift;
  for (uint32_t m = 0; m < meshes_.size(); ++m) {
    const Mesh& mesh = meshes_[m];
    if (!mesh.deformable || mesh.sah_at_rebuild <= 0.0) continue;
    const double now = m < measured.size() && measured[m] ? *measured[m] : accel::sah_cost(mesh.bvh, options_.build);
    drift = std::max(drift.value_or(0.0), now / mesh.sah_at_rebuild);
  }
  return drift;
}

}  // namespace glint::gl_rt
