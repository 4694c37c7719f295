#include "accel/tlas.h"

#include "accel/refit.h"
#include "accel/trace.h"
#include "core/error.h"
#include "core/math.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <chrono>
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

std::vector<Aabb> instance_world_boxes(std::span<const Blas> blases, std::span<const Instance> instances) {
  std::vector<Aabb> boxes(instances.size());
  for (size_t i = 0; i < instances.size(); ++i) {
    const Instance& instance = instances[i];
    if (instance.blas >= blases.size())
      fail("accel: instance {} uses BLAS {} of {}", i, instance.blas, blases.size());
    const BvhView& blas = blases[instance.blas].bvh;
    if (blas.node_count > 0) boxes[i] = transform_aabb(instance.object_to_world, blas.nodes[0].bounds());
  }
  return boxes;
}

Tlas build_tlas(std::span<const Blas> blases, std::vector<Instance> instances, BvhBuilder builder,
                const BuildOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  Tlas tlas;
  tlas.instances = std::move(instances);
  const std::vector<Aabb> boxes = instance_world_boxes(blases, tlas.instances);
  std::vector<vec3> centroids(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    // An empty instance still needs a sort key: its origin in world space.
    centroids[i] = boxes[i].empty() ? vec3(tlas.instances[i].object_to_world[3]) : boxes[i].center();
  }
  tlas.bvh = build_bvh(builder, BuildInput{boxes, centroids}, options);
  tlas.bvh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return tlas;
}

void refit_tlas(Tlas& tlas, std::span<const Blas> blases) {
  refit(tlas.bvh, instance_world_boxes(blases, tlas.instances));
}

}  // namespace glint::accel
