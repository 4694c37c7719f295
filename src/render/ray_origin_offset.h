#pragma once
// How far a secondary ray's origin is pushed off its surface along the normal (shadow rays, reflection
// rays and the reflection hits' shadow rays): `fraction` of the scene's bounds diagonal, as always,
// but never less than kRayOriginOffsetSteps float steps of the scene's largest coordinate. Far from the
// origin the G-buffer's world positions are float coordinates of that size, rounded (and interpolated)
// to a few steps, which a fraction of a small scene's diagonal does not cover: at 1e5 a step is
// 0.0078, a small room's 1e-4 x diagonal 0.001, and the rays would start under their own surface
// (acne). At the origin the steps are far below the diagonal's share (the atrium: 2.4e-5 against
// 0.0046), so scenes there keep their offset exactly. fraction 0 stays 0 (no offset asked for).
#include "core/math.h"

namespace glint::render {

inline constexpr float kRayOriginOffsetSteps = 8.0f;

float ray_origin_offset(float fraction, const Aabb& world_bounds);

}  // namespace glint::render
