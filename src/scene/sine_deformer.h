#pragma once
// The paper's "sine wave algorithm" for deformable meshes: every vertex moves along one axis by
// amplitude * sin(frequency * rest[wave_axis] + speed * t), then smooth normals are recomputed.
// Positions always come from the rest pose, never from the previous frame, so a frame's geometry
// depends only on its time (frames can be rendered in any order, and errors never accumulate).
#include "scene/scene.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace glint {

class SineDeformer {
public:
  // Keeps the rest positions and a vertex -> triangles adjacency of `rest_mesh` (for the normals).
  // Throws glint::Error for an axis outside 0..2, non-finite parameters, or an index out of range.
  SineDeformer(const Mesh& rest_mesh, SineDeform parameters);

  // Overwrites mesh.positions and mesh.normals with the pose at `time_seconds`; indices, UVs and
  // everything else are left alone. `mesh` must have the rest mesh's vertices and triangles; a
  // different vertex or index count throws glint::Error. Parallel (TBB) over vertices and triangles.
  // Not const: it reuses a face-normal buffer sized once, so the per-frame path allocates nothing.
  void apply(Mesh& mesh, float time_seconds);

  const SineDeform& parameters() const { return parameters_; }
  std::size_t vertex_count() const { return rest_positions_.size(); }
  // What a GPU deformer uploads to pose the mesh the same way (cuda/gpu_sine_deformer.h).
  const std::string& mesh_name() const { return mesh_name_; }
  const std::vector<vec3>& rest_positions() const { return rest_positions_; }
  const std::vector<std::uint32_t>& indices() const { return indices_; }
  const std::vector<std::size_t>& vertex_offsets() const { return vertex_offsets_; }
  const std::vector<std::uint32_t>& vertex_triangles() const { return vertex_triangles_; }

private:
  std::string mesh_name_;  // for error messages
  SineDeform parameters_;
  std::vector<vec3> rest_positions_;
  std::vector<std::uint32_t> indices_;
  // Compressed adjacency: the triangles around vertex v are
  // vertex_triangles_[vertex_offsets_[v] .. vertex_offsets_[v + 1]), in ascending order (a triangle
  // appears once per corner it has at v). Gathering per vertex needs no atomics, and the ascending
  // order makes the sums bit-identical to compute_smooth_normals' scatter.
  std::vector<std::size_t> vertex_offsets_;
  std::vector<std::uint32_t> vertex_triangles_;
  std::vector<vec3> face_normals_;  // scratch for apply, one per triangle
};

// One SineDeformer per deformable mesh of a scene (Mesh::deformable with Mesh::deform set).
class SceneDeformers {
public:
  // Throws glint::Error when the walkthrough's frames_per_second is not > 0 or a deformer's
  // parameters are invalid (the message names the mesh).
  explicit SceneDeformers(const Scene& scene);

  // Poses every deformable mesh of `scene` (the scene given to the constructor, or one with the same
  // meshes) at time frame / frames_per_second and returns the indices of the meshes it changed, in
  // ascending order: the dirty list for the acceleration structures. Throws for a negative frame or
  // a scene with a different number of meshes.
  std::vector<std::uint32_t> apply(Scene& scene, int frame);

  // The indices of the meshes this deforms (what apply returns).
  const std::vector<std::uint32_t>& meshes() const { return mesh_indices_; }
  const std::vector<SineDeformer>& deformers() const { return deformers_; }  // parallel to meshes()
  bool empty() const { return deformers_.empty(); }
  // The time apply(frame) poses the meshes at (seconds).
  float time_at(int frame) const;

private:
  std::vector<std::uint32_t> mesh_indices_;
  std::vector<SineDeformer> deformers_;
  std::size_t scene_mesh_count_ = 0;
  float frames_per_second_ = 30.0f;
};

}  // namespace glint
