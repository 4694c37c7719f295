#pragma once
// Reflection-like rays for the rt tests: what the hybrid renderer sends where SSR failed, rays that
// start on the scene's surfaces and leave them in random directions.
#include "accel/ray.h"
#include "scene/scene.h"

#include <cstdint>
#include <vector>

namespace glint::testing {

// `count` rays, each from a uniformly random point of a random world triangle (every instance of
// every mesh) into a uniformly random direction of the hemisphere around that triangle's geometric
// normal, unit length, t in [1e-4 x scene diagonal, infinity) so the ray does not hit its own
// triangle. Deterministic for a seed.
std::vector<accel::Ray> reflection_like_rays(const Scene& scene, size_t count, uint32_t seed);

}  // namespace glint::testing
