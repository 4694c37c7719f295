#include "app/accel_bench/ray_generation.h"

#include "core/error.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <random>

namespace glint::accel_bench {

accel::Ray PinholeCamera::ray_through(float px, float py) const {
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  // Image point -> [-1, 1] on both axes (y up), scaled to the image plane at distance 1.
  const float sx = (2.0f * px / static_cast<float>(width) - 1.0f) * aspect * tan_half_fov_y;
  const float sy = (1.0f - 2.0f * py / static_cast<float>(height)) * tan_half_fov_y;
  accel::Ray ray;
  ray.origin = position;
  ray.direction = glm::normalize(forward + sx * right + sy * up);
  return ray;
}

PinholeCamera make_pinhole_camera(const CameraState& camera, int width, int height) {
  if (width < 1 || height < 1) fail("accel-bench: image size {}x{} must be at least 1x1", width, height);
  // The camera-to-world rotation is the transpose of the view matrix's rotation: its rows are the
  // camera's right, up and backward axes in world space.
  const mat4 view = camera.view();
  PinholeCamera pinhole;
  pinhole.position = camera.position;
  pinhole.right = glm::normalize(vec3(view[0][0], view[1][0], view[2][0]));
  pinhole.up = glm::normalize(vec3(view[0][1], view[1][1], view[2][1]));
  pinhole.forward = -glm::normalize(vec3(view[0][2], view[1][2], view[2][2]));
  pinhole.tan_half_fov_y = std::tan(glm::radians(camera.fov_y_degrees) * 0.5f);
  pinhole.width = width;
  pinhole.height = height;
  return pinhole;
}

std::vector<accel::Ray> primary_rays(const PinholeCamera& camera) {
  std::vector<accel::Ray> rays;
  rays.reserve(static_cast<size_t>(camera.width) * static_cast<size_t>(camera.height));
  for (int y = 0; y < camera.height; ++y)
    for (int x = 0; x < camera.width; ++x)
      rays.push_back(camera.ray_through(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f));
  return rays;
}

std::vector<accel::Ray> reflection_rays(std::span<const accel::Ray> primary, std::span<const accel::Hit> hits,
                                        const rt::SceneGeometry& geometry, const Scene& scene) {
  if (primary.size() != hits.size()) fail("accel-bench: {} primary rays but {} hits", primary.size(), hits.size());
  const accel::TriangleMesh mesh = geometry.mesh();
  std::vector<accel::Ray> rays;
  for (size_t i = 0; i < primary.size(); ++i) {
    const accel::Hit& hit = hits[i];
    if (!hit.valid()) continue;
    if (hit.prim >= geometry.sources.size()) fail("accel-bench: hit on triangle {} of {}", hit.prim, geometry.sources.size());
    const Material& material = scene.materials[scene.meshes[geometry.sources[hit.prim].mesh].material];
    if (!(material.reflectivity > 0.0f)) continue;
    const accel::Triangle tri = mesh.triangle(hit.prim);
    vec3 normal = glm::cross(tri.v1 - tri.v0, tri.v2 - tri.v0);
    const float length = glm::length(normal);
    if (!(length > 0.0f)) continue;  // degenerate triangle: no normal to reflect about
    normal /= length;
    const vec3 d = primary[i].direction;
    if (glm::dot(normal, d) > 0.0f) normal = -normal;
    // The point from barycentrics is on the triangle's plane to rounding, unlike origin + t d.
    const vec3 point = (1.0f - hit.u - hit.v) * tri.v0 + hit.u * tri.v1 + hit.v * tri.v2;
    const vec3 magnitude = glm::abs(point);
    const float offset = kReflectionOffset * std::max({1.0f, magnitude.x, magnitude.y, magnitude.z});
    accel::Ray ray;
    ray.origin = point + offset * normal;
    ray.direction = d - 2.0f * glm::dot(d, normal) * normal;
    rays.push_back(ray);
  }
  return rays;
}

std::vector<accel::Ray> random_rays(const Aabb& bounds, size_t count, uint32_t seed) {
  if (bounds.empty()) fail("accel-bench: random rays need a non-empty box");
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::vector<accel::Ray> rays(count);
  for (accel::Ray& ray : rays) {
    const vec3 f(unit(rng), unit(rng), unit(rng));
    ray.origin = bounds.min + f * (bounds.max - bounds.min);
    // Uniform on the sphere: z uniform in [-1, 1], azimuth uniform (Archimedes).
    const float z = 2.0f * unit(rng) - 1.0f;
    const float phi = glm::two_pi<float>() * unit(rng);
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    ray.direction = vec3(r * std::cos(phi), r * std::sin(phi), z);
  }
  return rays;
}

}  // namespace glint::accel_bench
