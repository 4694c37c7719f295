#include "accel/tlas.h"

#include "accel/refit.h"
#include "accel/trace.h"
#include "core/error.h"
#include "core/stopwatch.h"
#include "core/math.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <cmath>

namespace glint::accel {

Blas make_blas(const Bvh& bvh, const TriangleMesh& mesh) {
  // The same checks as a single-level batch (references of spatial-split BVHs included).
  check_traceable(bvh, mesh.triangle_count, "triangles of a BLAS mesh");
  return {bvh.view(), mesh};
}

Instance make_instance(uint32_t blas, const mat4& object_to_world) {
  if (!is_finite(object_to_world)) fail("accel: instance transform is not finite");
  if (glm::determinant(object_to_world) == 0.0f) fail("accel: instance transform is singular");
  Instance instance;
  instance.object_to_world = object_to_world;
  instance.world_to_object = glm::inverse(object_to_world);
  instance.blas = blas;
  if (!is_finite(instance.world_to_object)) fail("accel: instance transform cannot be inverted in float");
  return instance;
}

namespace {

std::vector<Aabb> root_boxes(std::span<const Blas> blases) {
  std::vector<Aabb> boxes(blases.size());
  for (size_t b = 0; b < blases.size(); ++b)
    if (blases[b].bvh.node_count > 0) boxes[b] = blases[b].bvh.nodes[0].bounds();
  return boxes;
}

}  // namespace

std::vector<Aabb> instance_world_boxes(std::span<const Blas> blases, std::span<const Instance> instances) {
  return instance_world_boxes(root_boxes(blases), instances);
}

std::vector<Aabb> instance_world_boxes(std::span<const Aabb> blas_boxes, std::span<const Instance> instances) {
  std::vector<Aabb> boxes(instances.size());
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& instance = instances[i];
    if (instance.blas >= blas_boxes.size())
      fail("accel: instance {} uses BLAS {} of {}", i, instance.blas, blas_boxes.size());
    if (!blas_boxes[instance.blas].empty())
      boxes[i] = transform_aabb(instance.object_to_world, blas_boxes[instance.blas]);
  }
  return boxes;
}

Tlas build_tlas(std::span<const Blas> blases, std::vector<Instance> instances, BvhBuilder builder,
                const BuildOptions& options) {
  return build_tlas(root_boxes(blases), std::move(instances), builder, options);
}

Tlas build_tlas(std::span<const Aabb> blas_boxes, std::vector<Instance> instances, BvhBuilder builder,
                const BuildOptions& options) {
  const Stopwatch watch;
  Tlas tlas;
  tlas.instances = std::move(instances);
  const std::vector<Aabb> boxes = instance_world_boxes(blas_boxes, tlas.instances);
  std::vector<vec3> centroids(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    // An empty instance still needs a sort key: its origin in world space.
    centroids[i] = boxes[i].empty() ? vec3(tlas.instances[i].object_to_world[3]) : boxes[i].center();
  }
  tlas.bvh = build_bvh(builder, BuildInput{boxes, centroids}, options);
  tlas.bvh.build_ms = watch.elapsed_ms();
  return tlas;
}

void refit_tlas(Tlas& tlas, std::span<const Blas> blases) {
  refit(tlas.bvh, instance_world_boxes(blases, tlas.instances));
}

void refit_tlas(Tlas& tlas, std::span<const Aabb> blas_boxes) {
  refit(tlas.bvh, instance_world_boxes(blas_boxes, tlas.instances));
}

}  // namespace glint::accel
