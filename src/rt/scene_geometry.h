#pragma once
// A Scene flattened for ray tracing with a single-level structure: every instance's triangles
// transformed to world space and appended into one indexed triangle list, with a map from each
// world triangle back to where it came from (instance, mesh, triangle of the mesh), which is what
// shading a hit needs (material, normals, UVs).
#include "accel/triangle_mesh.h"
#include "scene/scene.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::rt {

// Where world triangle i came from.
struct TriangleSource {
  uint32_t instance = 0;        // index in Scene::instances
  uint32_t mesh = 0;            // index in Scene::meshes
  uint32_t local_triangle = 0;  // triangle index inside the mesh
};

// The contiguous block one instance occupies in the world arrays.
struct InstanceRange {
  uint32_t instance = 0;
  uint32_t mesh = 0;
  uint32_t first_vertex = 0;
  uint32_t vertex_count = 0;
  uint32_t first_triangle = 0;
  uint32_t triangle_count = 0;
};

struct SceneGeometry {
  std::vector<vec3> positions;         // world space, one block per instance
  std::vector<uint32_t> indices;       // three per world triangle, into `positions`
  std::vector<TriangleSource> sources; // one per world triangle
  std::vector<InstanceRange> instances;  // one per flattened instance, in flattening order
  // The blocks of instances whose mesh is deformable (Mesh::deformable): what update_deformed
  // rewrites and what a refit has to cover.
  std::vector<InstanceRange> deformable;

  // The accel view of the world triangles; valid while this object lives and is not resized.
  accel::TriangleMesh mesh() const;
  uint32_t triangle_count() const { return static_cast<uint32_t>(sources.size()); }
  Aabb bounds() const;
};

// Flattens every instance of `scene`. glint::Error when the scene is invalid (Scene::validate) or
// there are more than 2^32 - 2 world vertices or triangles.
SceneGeometry flatten_scene(const Scene& scene);

// Flattens only the instances of the meshes in `mesh_indices` (e.g. Scene::deformable_meshes(), to
// build a structure over the deforming creatures alone). glint::Error for a mesh index out of range.
SceneGeometry flatten_scene(const Scene& scene, std::span<const uint32_t> mesh_indices);

// After a deformer moved the vertices of the meshes in `dirty_meshes` (e.g. what SceneDeformers::apply
// returns), rewrites the world positions of every instance of them; nothing else changes, so a refit
// over geometry.mesh() is valid. glint::Error when a mesh's vertex count no longer matches its block.
void update_deformed(SceneGeometry& geometry, const Scene& scene, std::span<const uint32_t> dirty_meshes);

}  // namespace glint::rt
