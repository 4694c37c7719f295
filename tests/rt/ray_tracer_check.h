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

// make_instanced_scene(16) with the sheet's (mesh 2's) wave made strong enough to wreck a refitted
// BVH: its SAH cost after a refit grows well past the one it was built with.
Scene make_strongly_deforming_scene();

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

// The occlusion query (RayTracer::trace_any) by brute force: 1 when any world triangle of `scene` is
// hit within [t_min, t_max] by the same watertight test the backends use, else 0.
std::vector<uint8_t> brute_force_occluded(const Scene& scene, std::span<const accel::Ray> rays);

// Occlusion of `rays` by `tracer` (trace_any).
std::vector<uint8_t> trace_occluded(const rt::RayTracer& tracer, std::span<const accel::Ray> rays);

// Whether each closest hit exists: what trace_any must answer for the same rays.
std::vector<uint8_t> hit_exists(std::span<const accel::Hit> hits);

// "" when the two occlusion lists are equal; else the first few differing rays and the count.
std::string compare_occluded(std::span<const accel::Ray> rays, std::span<const uint8_t> expected,
                             std::span<const uint8_t> actual);

// Rays that probe an occlusion query's edge cases on `scene`, from `rays` and their brute-force closest
// hits `hits`: for every hit at t, the same ray ending just before it (t_max = t (1 - 1e-3)), just
// after it (t (1 + 1e-3)), and starting just past it (t_min = t (1 + 1e-3), t_max kept).
std::vector<accel::Ray> hit_interval_probe_rays(std::span<const accel::Ray> rays, std::span<const accel::Hit> hits);

// Rays aimed exactly at interior shared edges (midpoints) and interior vertices of the world triangles
// (edges shared by two triangles, vertices all of whose edges are): from a random point at a distance
// of 0.5 to 3 scene units off the surface (direction at least 0.3 from grazing), reaching the target
// at t = 1, unbounded. A watertight test hits one of the triangles around the target in any space
// (world or an instance's object space), so every one is occluded for a correct backend; a test
// with cracks lets some through. At most `max_per_kind` edges and as many vertices, deterministic
// for a seed.
std::vector<accel::Ray> edge_and_vertex_rays(const Scene& scene, size_t max_per_kind, uint32_t seed);

// Every kind of ray the occlusion tests check: random_rays(scene, random_count, seed), edge and
// vertex rays (random_count / 4 of each kind), and the interval probes around all of their
// brute-force hits.
std::vector<accel::Ray> occlusion_test_rays(const Scene& scene, size_t random_count, uint32_t seed);

}  // namespace glint::testing
