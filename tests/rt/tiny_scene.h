#pragma once
// A small scene built in code for the rt and accel-bench tests: a mirror floor, a matte wall, and
// a deformable waving sheet drawn twice, with a walkthrough camera looking at them.
#include "scene/scene.h"

namespace glint::testing {

// Meshes: 0 "floor" (quad, y = 0, x and z in [-10, 10], material 0 reflectivity 0.5),
// 1 "wall" (quad at z = -5, material 1, reflectivity 0), 2 "sheet" (cells x cells grid in its own
// x-y plane, deformable with a sine wave, material 1). Instances: floor, wall, sheet translated to
// (-2, 1, 0) and sheet rotated 90 degrees about y and translated to (3, 1, 1).
Scene make_tiny_scene(int sheet_cells = 8);

}  // namespace glint::testing
