#pragma once
// Two levels whose BLASes are kd-trees: the TLAS (accel/tlas.h, a BVH over instances built from the
// kd-trees' root cells) is walked by tlas_traverse.h's walk, and at an instance leaf the ray, moved
// into the instance's object space by the same to_object_space, walks that mesh's kd-tree with the
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

// The two-level walks of tlas_traverse.h (trace_closest/trace_any(const KdTlasView&, ray)) with a
// kd-tree BLAS, walked through its KdTreeView.
using KdTlasView = TwoLevelView<KdBlas>;

GLINT_HOST_DEVICE inline const KdTreeView& blas_structure(const KdBlas& blas) { return blas.tree; }

// CPU batches (TBB-parallel over rays), as tlas_trace.h's: `blases` is the array the TLAS was built
// with. glint::Error when the spans differ in size or an instance names a BLAS past the end.
void trace_closest(const Tlas& tlas, std::span<const KdBlas> blases, std::span<const Ray> rays, std::span<Hit> hits);
void trace_any(const Tlas& tlas, std::span<const KdBlas> blases, std::span<const Ray> rays,
               std::span<uint8_t> occluded);

}  // namespace glint::accel
