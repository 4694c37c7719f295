#pragma once
// Two levels: one BLAS (a Bvh over one mesh's triangles) per mesh, and a TLAS, a Bvh over
// instances (a BLAS plus a transform) built by the same builders from the instances' world boxes.
// Moving an instance touches only the TLAS, which is small: rebuild or refit it every frame.
#include "accel/builders/builder.h"
#include "accel/bvh.h"
#include "accel/triangle_mesh.h"

#include <span>
#include <type_traits>
#include <vector>

namespace glint::accel {

// What traversal needs of a BLAS: views only, so an array of them can live on the device.
struct Blas {
  BvhView bvh;
  TriangleMesh mesh;
};

// glint::Error when the BVH was not built over mesh's triangles or is too deep to traverse.
Blas make_blas(const Bvh& bvh, const TriangleMesh& mesh);

// Ray traversal maps world rays to object space with world_to_object, so it is stored, not
// recomputed per ray. t is the same in both spaces (the direction is transformed unnormalised).
struct Instance {
  mat4 object_to_world{1.0f};
  mat4 world_to_object{1.0f};
  uint32_t blas = 0;  // index into the Blas array given to build_tlas / tracing
};

static_assert(std::is_trivially_copyable_v<Instance>);

// Computes the inverse; glint::Error when the transform is singular or not finite.
Instance make_instance(uint32_t blas, const mat4& object_to_world);

struct Tlas {
  Bvh bvh;                          // over instances: prim_indices are instance indices
  std::vector<Instance> instances;  // Hit.instance indexes this
};

// The world box of every instance: its BLAS root box transformed (an empty BLAS gives an empty
// box). glint::Error when an instance names a BLAS past the end of `blases`.
std::vector<Aabb> instance_world_boxes(std::span<const Blas> blases, std::span<const Instance> instances);
// The same from each BLAS's object-space root box (empty for an empty BLAS), for BLASes of any kind
// (the kd-tree's, accel/kdtree/kdtree_tlas.h).
std::vector<Aabb> instance_world_boxes(std::span<const Aabb> blas_boxes, std::span<const Instance> instances);

Tlas build_tlas(std::span<const Blas> blases, std::vector<Instance> instances, BvhBuilder builder,
                const BuildOptions& options = {});
Tlas build_tlas(std::span<const Aabb> blas_boxes, std::vector<Instance> instances, BvhBuilder builder,
                const BuildOptions& options = {});

// After instance transforms changed (edit tlas.instances through make_instance) or BLASes were
// refitted: refits the TLAS boxes, keeping its topology.
void refit_tlas(Tlas& tlas, std::span<const Blas> blases);
void refit_tlas(Tlas& tlas, std::span<const Aabb> blas_boxes);

}  // namespace glint::accel
