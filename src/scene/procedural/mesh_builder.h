#pragma once
// Appends tessellated surfaces to a Mesh with shared vertices: parametric patches (the one
// primitive everything else is built from), boxes, walls with rectangular openings and surfaces
// of revolution. Every surface is oriented by a `facing` direction the caller knows (the outward
// side), so winding and normals can never disagree: the builder computes the patch's own normal
// and flips the patch when it points away from `facing`.
#include "core/math.h"
#include "scene/scene.h"

#include <functional>
#include <vector>

namespace glint::procedural {

// A point on a surface for parameters (u, v) in [0, 1]^2.
using SurfaceFn = std::function<vec3(float u, float v)>;

// Texture coordinates of a patch: uv = offset + (u, v) * scale (so `scale` is how many times the
// texture repeats across the patch).
struct UvMap {
  vec2 offset{0.0f};
  vec2 scale{1.0f};
};

// Number of segments for a length at a maximum segment size (at least `minimum`).
int segments_for(float length, float max_segment, int minimum = 1);

class MeshBuilder {
public:
  explicit MeshBuilder(Mesh& mesh) : mesh_(mesh) {}

  // A (nu + 1) x (nv + 1) vertex grid. Normals come from the surface's partial derivatives
  // (central differences in parameter space), so curved patches are smooth across their own
  // interior and agree with neighbouring patches of the same surface. `facing` is the direction the
  // front side must face at the patch's centre.
  void add_patch(int nu, int nv, const SurfaceFn& surface, const UvMap& uv, vec3 facing);
  // The same with texture coordinates from the point and its parameters (e.g. planar world
  // projection, so neighbouring patches of one wall share one texture layout).
  using UvFn = std::function<vec2(const vec3& point, float u, float v)>;
  void add_patch(int nu, int nv, const SurfaceFn& surface, const UvFn& uv, vec3 facing);

  // A planar rectangle corner + s * edge_u + t * edge_v, tessellated to at most `max_segment`.
  // Its front faces along cross(edge_u, edge_v) unless `facing` says otherwise.
  void add_rectangle(vec3 corner, vec3 edge_u, vec3 edge_v, float max_segment, float uv_metres, vec3 facing);

  // An axis-aligned box's outward faces; `faces` masks which of -x,+x,-y,+y,-z,+z (bits 0..5).
  void add_box(vec3 min, vec3 max, float max_segment, float uv_metres, unsigned faces = 0x3Fu);

  // A planar wall rectangle (corner, edge_u, edge_v) with rectangular openings given in (s, t)
  // metres along the edges; the grid lines follow the openings' edges so the holes are exact.
  struct Opening {
    float s0, s1, t0, t1;
  };
  void add_wall(vec3 corner, vec3 edge_u, vec3 edge_v, const std::vector<Opening>& openings, float max_segment,
                float uv_metres, vec3 facing);

  // A surface of revolution around the vertical axis through `base`: `profile` lists (radius,
  // height) points; `angular` segments around. Smooth across profile points; use separate calls
  // for creases. Faces outwards (away from the axis).
  void add_lathe(vec3 base, const std::vector<vec2>& profile, int angular, float uv_metres);

  // Removes vertices no triangle uses (walls with openings leave some behind).
  void compact();

private:
  Mesh& mesh_;
};

}  // namespace glint::procedural
