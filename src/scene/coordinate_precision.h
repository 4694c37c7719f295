#pragma once
// Positions are floats from the file reader to the G-buffer: a model far from the origin against its
// own size keeps only a few distinct coordinates across it (the Stanford bunny, 0.16 units, moved
// 1e5 away, where floats are 0.0078 apart: 20 steps across, 53k of its 69k triangles collapsed and
// the rest drawn as blocks). Nothing can restore what the reader rounded, so glint says so.
#include "scene/scene.h"

#include <cstddef>

namespace glint {

// Fewer float steps than this across an instance's largest extent (at its largest coordinate) is
// coarse: 256 steps is 8-bit precision, where facets and blocks show in a frame.
inline constexpr double kMinCoordinateStepsAcross = 256.0;

// One warning naming `scene.source`, the coarsest instance, its size, distance and float step, and
// how many instances are coarse; nothing when none is.
void warn_about_coarse_coordinates(const Scene& scene);

}  // namespace glint
