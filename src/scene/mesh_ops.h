#pragma once
// Geometry clean-up shared by the loaders, the procedural scenes and the deformers.
#include "scene/scene.h"

#include <cstddef>

namespace glint {

// Area-weighted average of the faces around each vertex; vertices on no (non-degenerate) face get
// +y. Every normal is unit length afterwards.
void compute_smooth_normals(Mesh& mesh);

// Every triangle gets its own three vertices carrying the face normal (UVs are duplicated too).
void compute_flat_normals(Mesh& mesh);

// True when the triangle has zero area: a repeated index, or edges that are (numerically) parallel.
bool is_degenerate_triangle(const vec3& a, const vec3& b, const vec3& c);

// Drops zero-area triangles and returns how many were dropped. Vertices are kept (they may be
// shared with other triangles); unused ones are harmless.
std::size_t remove_degenerate_triangles(Mesh& mesh);

}  // namespace glint
