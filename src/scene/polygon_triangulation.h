#pragma once
// Splits one polygonal face (an OBJ `f` line with more than three corners) into triangles.
// tinyobjloader's own triangulation (2.0.0rc10, Debian's) fans concave polygons across their notch
// and turns some into slivers (an L-shaped floor covered the notch, or lost two thirds of its area),
// so the OBJ loader reads faces untriangulated and splits them here.
#include "core/math.h"

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace glint {

// Ear clipping in the polygon's own plane (the Newell normal's), in double precision. Returns
// triangles as corner indices into `corners`, wound like the polygon (so the face keeps its front
// side), n - 2 of them for a simple polygon of n corners, none with a corner of the polygon inside.
// A convex quad is split along its shorter diagonal. Collinear corners (points on an edge) stay
// corners of the triangles. A self-intersecting or degenerate polygon still gives n - 2 triangles
// or fewer (never an endless loop); they may overlap or have zero area, which the loader drops.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const vec3> corners);

}  // namespace glint
