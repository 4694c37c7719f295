// accel-bench's rays: checked against an independent projection (glm::perspective) and the mirror law.
#include "accel/builders/builder.h"
#include "accel/trace.h"
#include "app/accel_bench/ray_generation.h"
#include "core/error.h"
#include "rt/scene_geometry.h"
#include "rt/tiny_scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace glint::accel_bench {
namespace {

CameraState tilted_camera() {
  CameraState camera;
  camera.position = vec3(1.0f, 2.0f, 3.0f);
  camera.target = vec3(-2.0f, 0.5f, -4.0f);
  camera.fov_y_degrees = 50.0f;
  return camera;
}

TEST(AccelBenchRays, PrimaryRaysPassThroughThePixelCentres) {
  const CameraState camera = tilted_camera();
  const int width = 16, height = 9;
  const std::vector<accel::Ray> rays = primary_rays(make_pinhole_camera(camera, width, height));
  ASSERT_EQ(rays.size(), 144u);
  // Project a point of every ray with the GL camera matrices: it must land on its pixel's centre
  // (NDC y up, pixel row 0 at the top).
  const mat4 projection =
      glm::perspective(glm::radians(camera.fov_y_degrees), static_cast<float>(width) / static_cast<float>(height), 0.1f, 100.0f);
  const mat4 view_projection = projection * camera.view();
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const accel::Ray& ray = rays[static_cast<size_t>(y * width + x)];
      EXPECT_EQ(ray.origin, camera.position);
      EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-5f);
      const vec4 clip = view_projection * vec4(ray.origin + 7.0f * ray.direction, 1.0f);
      ASSERT_GT(clip.w, 0.0f);  // in front of the camera
      const float px = (clip.x / clip.w * 0.5f + 0.5f) * static_cast<float>(width);
      const float py = (0.5f - clip.y / clip.w * 0.5f) * static_cast<float>(height);
      EXPECT_NEAR(px, static_cast<float>(x) + 0.5f, 1e-3f) << x << "," << y;
      EXPECT_NEAR(py, static_cast<float>(y) + 0.5f, 1e-3f) << x << "," << y;
    }
  EXPECT_THROW((void)make_pinhole_camera(camera, 0, 4), Error);
}

TEST(AccelBenchRays, ReflectionRaysObeyTheMirrorLawAtTheFloorOnly) {
  const Scene scene = glint::testing::make_tiny_scene(4);
  const rt::SceneGeometry geometry = rt::flatten_scene(scene);
  const accel::TriangleMesh mesh = geometry.mesh();
  const accel::Bvh bvh = accel::build_bvh(accel::BvhBuilder::sah, mesh);
  CameraState camera;
  camera.position = vec3(0.5f, 3.0f, 7.0f);
  camera.target = vec3(0.0f, 0.0f, -3.0f);
  const std::vector<accel::Ray> primary = primary_rays(make_pinhole_camera(camera, 40, 30));
  std::vector<accel::Hit> hits(primary.size());
  accel::trace_closest(bvh, mesh, primary, hits);

  size_t floor_hits = 0, other_hits = 0;
  std::vector<vec3> expected_origins, expected_directions;
  for (size_t i = 0; i < primary.size(); ++i) {
    if (!hits[i].valid()) continue;
    if (geometry.sources[hits[i].prim].mesh != 0) {
      ++other_hits;
      continue;
    }
    ++floor_hits;
    const vec3 d = primary[i].direction;
    expected_origins.push_back(primary[i].origin + hits[i].t * d);
    expected_directions.push_back(vec3(d.x, -d.y, d.z));  // mirror about the floor's normal +y
  }
  ASSERT_GT(floor_hits, 100u);
  ASSERT_GT(other_hits, 50u);  // the matte wall and sheets are seen too, and must not reflect

  const std::vector<accel::Ray> reflected = reflection_rays(primary, hits, geometry, scene);
  ASSERT_EQ(reflected.size(), floor_hits);
  for (size_t i = 0; i < reflected.size(); ++i) {
    const accel::Ray& ray = reflected[i];
    EXPECT_NEAR(ray.direction.x, expected_directions[i].x, 1e-5f);
    EXPECT_NEAR(ray.direction.y, expected_directions[i].y, 1e-5f);
    EXPECT_NEAR(ray.direction.z, expected_directions[i].z, 1e-5f);
    EXPECT_GT(ray.direction.y, 0.0f);  // away from the floor
    // On the floor's hit point, lifted off it along +y by the offset (|coordinates| <= 10 here).
    EXPECT_NEAR(ray.origin.x, expected_origins[i].x, 1e-4f);
    EXPECT_NEAR(ray.origin.z, expected_origins[i].z, 1e-4f);
    EXPECT_GT(ray.origin.y, 0.0f);
    EXPECT_LE(ray.origin.y, 10.0f * kReflectionOffset + 1e-6f);
    EXPECT_EQ(ray.t_min, 0.0f);
  }
  // Lifted off the surface, they do not hit the floor they start on.
  std::vector<accel::Hit> second(reflected.size());
  accel::trace_closest(bvh, mesh, reflected, second);
  for (const accel::Hit& hit : second) {
    if (hit.valid()) {
      EXPECT_NE(geometry.sources[hit.prim].mesh, 0u);
    }
  }
}

TEST(AccelBenchRays, RandomRaysAreReproduciblePerSeedAndUniform) {
  Aabb box;
  box.extend(vec3(-1.0f, 2.0f, 3.0f));
  box.extend(vec3(4.0f, 5.0f, 9.0f));
  const std::vector<accel::Ray> a = random_rays(box, 20000, 7), b = random_rays(box, 20000, 7),
                                c = random_rays(box, 20000, 8);
  ASSERT_EQ(a.size(), 20000u);
  size_t same_as_other_seed = 0;
  vec3 mean_direction(0.0f), mean_origin(0.0f);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].origin, b[i].origin);
    EXPECT_EQ(a[i].direction, b[i].direction);
    same_as_other_seed += a[i].origin == c[i].origin ? 1 : 0;
    EXPECT_TRUE(box.contains(a[i].origin));
    EXPECT_NEAR(glm::length(a[i].direction), 1.0f, 1e-5f);
    mean_direction += a[i].direction / 20000.0f;
    mean_origin += a[i].origin / 20000.0f;
  }
  EXPECT_EQ(same_as_other_seed, 0u);
  EXPECT_LT(glm::length(mean_direction), 0.03f);  // uniform on the sphere: mean ~ 0 (sd ~ 0.007)
  EXPECT_LT(glm::length(mean_origin - box.center()), 0.05f);
  EXPECT_THROW((void)random_rays(Aabb{}, 1, 1), Error);
}

}  // namespace
}  // namespace glint::accel_bench
