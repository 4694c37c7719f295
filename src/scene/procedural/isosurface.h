#pragma once
// Polygonisation of an implicit surface (the zero set of a signed field, negative inside) by naive
// surface nets: one vertex per grid cell whose corners change sign, placed at the mean of the
// sign-changing edges' crossings; one quad (two triangles) across every sign-changing grid edge,
// joining the four cells around it. This needs no case tables, and because every quad is built
// from the grid's signs alone, the result is closed when the field is positive on the grid border.
// Orientation follows the edge's sign direction, so all faces point out of the negative region.
//
// The field is evaluated only near the surface: the grid is split into blocks of 8^3 cells, a block
// whose centre value shows it is far from the surface gets that sign everywhere, and the others are
// evaluated point by point in parallel (TBB). If the field changes faster than the test assumes
// (some quad would miss a cell), the grid is re-evaluated everywhere, so the mesh stays closed.
#include "core/math.h"
#include "scene/scene.h"

#include <cstddef>
#include <functional>

namespace glint::procedural {

// Must be a pure function (same input, same output) and safe to call from several threads.
using ScalarField = std::function<float(const vec3&)>;

// Surface nets on cubes of side `cell_size` over `bounds` (padded by two cells). Positions,
// unit normals (the normalised field gradient) and triangles; no UVs.
Mesh polygonize(const ScalarField& field, const Aabb& bounds, float cell_size);

// Only the number of vertices polygonize() would produce (cheaper: no normals, no faces).
std::size_t count_surface_vertices(const ScalarField& field, const Aabb& bounds, float cell_size);

// Chooses the cell size so the mesh has `target_vertices` within `tolerance` (relative): the count
// scales with 1 / cell_size^2, so each step rescales the cell size by sqrt(count / target) from a
// coarse first count. Deterministic; returns the closest mesh found within `max_steps` meshes.
struct TargetedMesh {
  Mesh mesh;
  float cell_size = 0.0f;
  int meshes_built = 0;
};
TargetedMesh polygonize_to_vertex_count(const ScalarField& field, const Aabb& bounds, std::size_t target_vertices,
                                        float tolerance = 0.01f, int max_steps = 5);

}  // namespace glint::procedural
