#pragma once
// Rays cast against a scene's world triangles on the CPU, for decisions taken at load time from the
// geometry itself (where the default camera and light go: default_walkthrough.cpp). One SAH BVH from
// accel/ over every instance's triangles in world space, each distinct triangle once (copies in the
// same place would make every ray test them all); no materials, no instancing, no updates.
#include "accel/bvh.h"
#include "accel/ray.h"
#include "core/math.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint {

struct ProbeHit {
  bool hit = false;
  float distance = 0.0f;     // along the ray's unit direction
  std::uint32_t triangle = 0;  // identifies the triangle hit (an index into the probe's own list)
  vec3 point{0.0f};
  // Unit geometric normal of the triangle, on its front side: the side from which its corners run
  // counter-clockwise, as OBJ and glTF define front faces. So a ray with dot(direction, normal) > 0
  // hits a back face, e.g. from inside a closed object whose faces point outwards.
  vec3 normal{0.0f, 1.0f, 0.0f};
};

class SceneRayProbe {
public:
  explicit SceneRayProbe(const Scene& scene);

  // Closest hit of each ray; directions must be unit vectors (distances are then lengths).
  std::vector<ProbeHit> closest(std::span<const accel::Ray> rays) const;

  const Aabb& bounds() const { return bounds_; }
  // The BVH's SAH cost: about how many boxes and triangles a ray through the scene tests. Tens for
  // real scenes; about the triangle count for geometry that overlaps itself everywhere.
  double ray_cost() const { return ray_cost_; }
  std::uint32_t triangle_count() const { return static_cast<std::uint32_t>(corners_.size() / 3); }

private:
  void remove_duplicate_triangles();

  std::vector<vec3> corners_;  // three per world triangle
  Aabb bounds_;
  accel::Bvh bvh_;
  double ray_cost_ = 0.0;
};

}  // namespace glint
