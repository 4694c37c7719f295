#pragma once
// The update policies' rule for one dirty mesh's BLAS, shared by the backends that update glint's own
// structures (cpu, cuda), so they refuse and decide alike. Header-only plain C++: .cu files include it.
//
// rebuild: built again. refit: boxes recomputed. automatic: refitted, and rebuilt once its SAH cost
// after a refit exceeds AccelOptions::auto_rebuild_sah_ratio x its cost right after its last
// (re)build. A structure that cannot be refitted (blas_structure_refittable: sbvh, kdtree) takes
// rebuild only: refit and automatic are refused before anything changes.
#include "rt/blas_structure.h"
#include "rt/ray_tracer.h"

#include <optional>
#include <string>
#include <string_view>

namespace glint::rt {

enum class BlasUpdate { rebuild, refit };

// The message of the glint::Error for updating a dirty mesh (`mesh_name`) of `structure` by `policy`
// on `backend`, or "" when that is fine (the policy rebuilds, or the structure can be refitted).
inline std::string update_refusal(std::string_view backend, UpdatePolicy policy, const BlasStructure& structure,
                                  std::string_view mesh_name) {
  if (policy == UpdatePolicy::rebuild || blas_structure_refittable(structure)) return {};
  const std::string name(blas_structure_name(structure));
  const std::string what = structure.kind == BlasKind::kdtree ? "the kdtree structure cannot be refitted (a kd-tree "
                                                                "update rebuilds it)"
                                                              : "the " + name + " builder's BVHs cannot be refitted";
  return "rt " + std::string(backend) + ": update policy '" + std::string(update_policy_name(policy)) +
         "' refits, but " + what + " (mesh '" + std::string(mesh_name) + "'); use policy rebuild or another " +
         (structure.kind == BlasKind::kdtree ? "structure" : "builder");
}

// What happens to a dirty mesh's BLAS. `sah_after_refit`: its SAH cost after a refit (cpu: the refit
// just done; cuda: the previous update's, read back a frame later), nullopt when not known, which
// keeps the refit; `sah_at_rebuild`: its cost right after its last (re)build (not positive: unknown).
inline BlasUpdate decide_blas_update(UpdatePolicy policy, std::optional<double> sah_after_refit, double sah_at_rebuild,
                                     double auto_rebuild_sah_ratio) {
  switch (policy) {
    case UpdatePolicy::rebuild: return BlasUpdate::rebuild;
    case UpdatePolicy::refit: return BlasUpdate::refit;
    case UpdatePolicy::automatic:
      return sah_after_refit && sah_at_rebuild > 0.0 && *sah_after_refit > auto_rebuild_sah_ratio * sah_at_rebuild
                 ? BlasUpdate::rebuild
                 : BlasUpdate::refit;
  }
  return BlasUpdate::rebuild;
}

}  // namespace glint::rt
