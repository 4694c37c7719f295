#pragma once
// The rays accel-bench traces, made on the CPU without GL: primary rays of a pinhole camera, mirror
// reflections of them at reflective surfaces (the rays the hybrid renderer hands to the ray tracer
// where SSR fails), and uniformly random rays.
#include "accel/ray.h"
#include "rt/scene_geometry.h"
#include "scene/camera_path.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::accel_bench {

// A pinhole camera with the walkthrough camera's position, orientation (CameraState::view) and
// vertical field of view over a width x height image. Pixel (x, y) has row 0 at the top.
struct PinholeCamera {
  vec3 position{0.0f};
  vec3 right{1.0f, 0.0f, 0.0f};    // world direction of +x on the image, unit
  vec3 up{0.0f, 1.0f, 0.0f};       // world direction of +y (up) on the image, unit
  vec3 forward{0.0f, 0.0f, -1.0f}; // viewing direction, unit
  float tan_half_fov_y = 0.0f;
  int width = 0;
  int height = 0;

  // The unit-direction ray from the camera through image point (px, py) in pixels, (0, 0) the top
  // left corner of the image; the centre of pixel (x, y) is (x + 0.5, y + 0.5).
  accel::Ray ray_through(float px, float py) const;
};

// glint::Error for a width or height below 1.
PinholeCamera make_pinhole_camera(const CameraState& camera, int width, int height);

// One ray per pixel through its centre, row-major from the top row: rays[y * width + x].
std::vector<accel::Ray> primary_rays(const PinholeCamera& camera);

// For every primary ray whose hit lies on a triangle with material reflectivity > 0: the mirror
// reflection r = d - 2 (d . n) n about the triangle's geometric normal n (turned to face the
// incoming ray), starting at the hit point moved off the surface along n by
// kReflectionOffset * max(1, largest |coordinate| of the point), with t in [0, infinity).
// `hits` are the closest hits of `primary` in `geometry` (instance/prim index geometry's triangles).
inline constexpr float kReflectionOffset = 1e-4f;
std::vector<accel::Ray> reflection_rays(std::span<const accel::Ray> primary, std::span<const accel::Hit> hits,
                                        const rt::SceneGeometry& geometry, const Scene& scene);

// `count` rays with origins uniform in `bounds` and directions uniform on the unit sphere, the same
// for the same seed (std::mt19937).
std::vector<accel::Ray> random_rays(const Aabb& bounds, size_t count, uint32_t seed);

}  // namespace glint::accel_bench
