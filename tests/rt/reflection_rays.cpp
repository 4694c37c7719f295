#include "rt/reflection_rays.h"

#include "rt/scene_geometry.h"

#include <cmath>
#include <random>

namespace glint::testing {

std::vector<accel::Ray> reflection_like_rays(const Scene& scene, size_t count, uint32_t seed) {
  const rt::SceneGeometry world = rt::flatten_scene(scene);
  const accel::TriangleMesh mesh = world.mesh();
  std::vector<accel::Ray> rays;
  if (world.triangle_count() == 0) return rays;
  const float t_min = 1e-4f * glm::length(world.bounds().extent());
  std::mt19937 rng(seed);
  std::uniform_int_distribution<uint32_t> pick(0, world.triangle_count() - 1);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::normal_distribution<float> gauss(0.0f, 1.0f);
  rays.reserve(count);
  while (rays.size() < count) {
    const accel::Triangle triangle = mesh.triangle(pick(rng));
    const vec3 normal = glm::cross(triangle.v1 - triangle.v0, triangle.v2 - triangle.v0);
    if (!(glm::length(normal) > 0.0f)) continue;  // degenerate: no hemisphere
    // Uniform barycentrics by folding the unit square onto the triangle.
    float a = unit(rng), b = unit(rng);
    if (a + b > 1.0f) a = 1.0f - a, b = 1.0f - b;
    // A uniform direction on the sphere, flipped into the normal's hemisphere.
    vec3 direction(gauss(rng), gauss(rng), gauss(rng));
    if (!(glm::length(direction) > 1e-6f)) continue;
    direction = glm::normalize(direction);
    if (glm::dot(direction, normal) < 0.0f) direction = -direction;
    accel::Ray ray;
    ray.origin = triangle.v0 + a * (triangle.v1 - triangle.v0) + b * (triangle.v2 - triangle.v0);
    ray.direction = direction;
    ray.t_min = t_min;
    rays.push_back(ray);
  }
  return rays;
}

}  // namespace glint::testing
