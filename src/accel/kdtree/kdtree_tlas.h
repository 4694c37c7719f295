#pragma once
// Two levels whose BLASes are kd-trees: the TLAS (accel/tlas.h, a BVH over instances built from the
// kd-trees' root cells) is walked as in tlas_traverse.h, and at an instance leaf the ray, moved into
// the instance's object space by the same to_object_space, walks that mesh's kd-tree with the
// current closest t as its limit. Single-ray walks for host and device, and the CPU batches.
#include "accel/kdtree/kdtree.h"
#include "accel/kdtree/kdtree_traverse.h"
#include "accel/ray.h"
#include "accel/tlas.h"
#include "accel/tlas_traverse.h"

#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

namespace glint::accel {

// What traversal needs of a kd-tree BLAS: views only, so an array of them can live on the device.
struct KdBlas {
  KdTreeView tree;
  TriangleMesh mesh;
};

static_assert(std::is_trivially_copyable_v<KdBlas>);

// glint::Error when the tree was not built over mesh's triangles or is deeper than traversal allows.
KdBlas make_kd_blas(const KdTree& tree, const TriangleMesh& mesh);

// Each BLAS's root cell (empty for an empty tree): what build_tlas/refit_tlas take.
std::vector<Aabb> kd_blas_boxes(std::span<const KdBlas> blases);

struct KdTlasView {
  BvhView bvh;
  const Instance* instances = nullptr;
  const KdBlas* blases = nullptr;
};

GLINT_HOST_DEVICE inline Hit trace_closest(const KdTlasView& tlas, const Ray& ray) {
  Hit hit;
  float t_max = ray.t_max;
  traverse_bvh<false>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t index, float& t_limit) {
    const Instance& instance = tlas.instances[index];
    const ObjectRay local = to_object_space(instance, ray);
    const KdBlas& blas = tlas.blases[instance.blas];
    if (!intersect_closest(blas.tree, blas.mesh, local.origin, local.direction, ray.t_min, t_limit, hit)) return false;
    hit.instance = index;
    return true;
  });
  return hit;
}

GLINT_HOST_DEVICE inline bool trace_any(const KdTlasView& tlas, const Ray& ray) {
  float t_max = ray.t_max;
  return traverse_bvh<true>(tlas.bvh, ray.origin, ray.direction, ray.t_min, t_max, [&](uint32_t index, float&) {
    const Instance& instance = tlas.instances[index];
    const ObjectRay local = to_object_space(instance, ray);
    const KdBlas& blas = tlas.blases[instance.blas];
    return intersect_any(blas.tree, blas.mesh, local.origin, local.direction, ray.t_min, ray.t_max);
  });
}

// CPU batches (TBB-parallel over rays), as tlas_trace.h's: `blases` is the array the TLAS was built
// with. glint::Error when the spans differ in size or an instance names a BLAS past the end.
void trace_closest(const Tlas& tlas, std::span<const KdBlas> blases, std::span<const Ray> rays, std::span<Hit> hits);
void trace_any(const Tlas& tlas, std::span<const KdBlas> blases, std::span<const Ray> rays,
               std::span<uint8_t> occluded);

}  // namespace glint::accel
