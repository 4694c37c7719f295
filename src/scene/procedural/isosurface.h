#pragma once
// Polygonisation of an implicit surface (the zero set of a signed field, negative inside) by naive
// surface nets: one vertex per grid cell whose corners change sign, placed at the mean of the
// sign-changing edges' crossings; one quad (two triangles) across every sign-changing grid edge,
// joining the four cells around it. This needs no case tables, and because every quad is built
// from the grid's signs alone, the result is closed when the field is positive on the grid border.
// Orientation follows the edge's sign direction, so all faces point out of the negative region.
//
// The field is evaluated only near the surface: the grid is split into blocks of 4^3 cells, a block
// whose centre value shows it is far from the surface gets that sign everywhere, and the others are
// evaluated point by point in parallel (TBB). If the field changes faster than the test assumes
// (some quad would miss a cell), the grid is re-evaluated everywhere, so the mesh stays closed.
#include "core/math.h"
#include "scene/procedural/implicit_field.h"
#include "scene/scene.h"

#include <cstddef>

namespace glint::procedural {

// Surface nets on cubes of side `cell_size` over `bounds` (padded by two cells). Positions,
// unit normals (the normalised field gradient) and triangles; no UVs.
// Ambiguous grid faces (corner signs alternating around the face) would join four quads at one
// edge; they are resolved by the field's value at the face centre (the corner nearest the surface
// takes the centre's sign), so every edge of the result has exactly two triangles.
Mesh polygonize(const ImplicitField& field, const Aabb& bounds, float cell_size);
Mesh polygonize(const ScalarField& field, const Aabb& bounds, float cell_size);

// Only the number of vertices polygonize() would produce (cheaper: no normals, no faces).
std::size_t count_surface_vertices(const ImplicitField& field, const Aabb& bounds, float cell_size);
std::size_t count_surface_vertices(const ScalarField& field, const Aabb& bounds, float cell_size);

// Chooses the cell size so the mesh has `target_vertices` within `tolerance` (relative): the count
// scales with about 1 / cell_size^2, so each step rescales the cell size by (count / target)^(1/p),
// starting from a coarse count and a count at half the predicted resolution (which also fit p), or
// from `initial_cell` when given (e.g. the cell size found for a similar shape). Deterministic;
// returns the closest mesh found within `max_steps` meshes.
struct TargetedMesh {
  Mesh mesh;
  float cell_size = 0.0f;
  int meshes_built = 0;
};
TargetedMesh polygonize_to_vertex_count(const ImplicitField& field, const Aabb& bounds, std::size_t target_vertices,
                                        float tolerance = 0.01f, int max_steps = 5, float initial_cell = 0.0f);
TargetedMesh polygonize_to_vertex_count(const ScalarField& field, const Aabb& bounds, std::size_t target_vertices,
                                        float tolerance = 0.01f, int max_steps = 5, float initial_cell = 0.0f);

}  // namespace glint::procedural
