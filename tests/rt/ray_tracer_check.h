#pragma once
// Test helpers for the RayTracer backends: scenes with instancing, random rays, and the reference
// every backend is checked against, a brute-force loop over rt::flatten_scene's world triangles.
#include "accel/ray.h"
#include "rt/ray_tracer.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace glint::testing {

// make_tiny_scene (floor, wall, deformable sheet drawn twice, once rotated) plus a third sheet
// instance rotated about a skew axis and scaled non-uniformly, and a closed tetrahedron mesh drawn
// twice (once translated, once rotated and scaled).
Scene make_instanced_scene(int sheet_cells = 8);

// atrium-simple cut down for a fast test: only the instances of the meshes named in `keep` (and of
// every deformable mesh, at most `max_deformable_instances` of them), unused meshes dropped.
Scene make_reduced_atrium(size_t max_deformable_instances = 2);

// Rays from random points of the scene's (slightly enlarged) bounds in random directions of random
// length (t is measured in units of the unnormalised direction); every fourth has a finite t_max.
std::vector<accel::Ray> random_rays(const Scene& scene, size_t count, uint32_t seed);

// Closest hits by brute force over the scene's world triangles, in the RayTracer hit convention.
std::vector<accel::Hit> brute_force_hits(const Scene& scene, std::span<const accel::Ray> rays);

// "" when `hits` equal the brute-force `expected` for `scene`: same hit/miss, t within 1e-4
// relative, same instance and local triangle unless the reported triangle is an exact tie (its own
// world-space t within the tolerance of the closest), u, v within 1e-3 for the same triangle.
// Otherwise a description of the first few differences.
std::string compare_hits(const Scene& scene, std::span<const accel::Ray> rays, std::span<const accel::Hit> expected,
                         std::span<const accel::Hit> hits);

// Traces `rays` with `tracer`.
std::vector<accel::Hit> trace(const rt::RayTracer& tracer, std::span<const accel::Ray> rays);

}  // namespace glint::testing
