#pragma once
// --deform-on gpu, GL's half: the scene's sine deformers as GL compute passes that pose the frame
// pipeline's vertex buffer in place (positions and smooth normals, as SineDeformer does on the CPU;
// shaders/sine_deform.comp.glsl), ordered with the raster passes by GL itself. Every mesh is posed in
// the same two dispatches (pose, then normals) over the meshes' arrays concatenated: a frame's cost
// is two dispatches' latency, not three per mesh. A GPU ray tracer's
// device positions are posed apart, by cuda::GpuSceneDeformer on the tracer's stream; neither side
// waits for the other, so a deforming frame has no GL-CUDA hand-over of its own (one cost about
// 0.33 ms of an H100 frame: docs/perf.md "Deforming without a hand-over").
#include "gl/compute_grid.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "scene/sine_deformer.h"

#include <cstdint>
#include <span>
#include <vector>

namespace glint::render {

class GlSceneDeformer {
public:
  // Uploads every deformer's rest pose and adjacency. `deformers` and `scene` must outlive this, and
  // `scene` must hold the deformers' meshes (glint::Error naming the mesh otherwise). Needs a current
  // GL context.
  GlSceneDeformer(const SceneDeformers& deformers, GpuScene& scene);

  // Poses every deformable mesh for walkthrough frame `frame` (SceneDeformers::time_at): the GL
  // commands are issued, nothing waits.
  void apply(int frame);

  // The scene meshes it poses, ascending (SceneDeformers::meshes).
  const std::vector<std::uint32_t>& meshes() const { return deformers_.meshes(); }

  // Makes every later apply() also write meshes()[k]'s object-space positions (vec4s, w 0) into
  // `buffer` from vec4 `first_vertex[k]` on, in its pose dispatch: the gl backend's positions
  // (rt::GlTracing::gl_positions), which its GPU refit then reads after apply()'s barrier, with no
  // copy between (a copy and its barrier took 0.04 ms of an H100 frame: docs/perf.md "Twelfth
  // round"). Cheap when nothing changed, so a caller may pass the tracer's current layout every
  // frame. glint::Error unless there is one first vertex per mesh.
  void write_positions_to(GLuint buffer, std::span<const std::uint32_t> first_vertex);

private:
  const SceneDeformers& deformers_;
  GpuScene& scene_;
  ShaderProgram program_;
  // Every mesh's arrays, one after the other (the shader's bindings 12 to 17), and one DeformJob
  // per mesh with vertices (binding 18).
  GlBuffer rest_, indices_, vertex_offsets_, vertex_triangles_, posed_, face_normals_, jobs_;
  // Per mesh of meshes() its job's index (-1: no vertices, no job), and per job the first vertex
  // of its write_positions_to() target as the jobs buffer holds it.
  std::vector<std::int32_t> job_of_mesh_;
  std::vector<std::uint32_t> target_first_vertex_;
  GLuint target_buffer_ = 0;  // write_positions_to()'s buffer; 0: none
  std::uint32_t job_count_ = 0;
  std::uint32_t pose_invocations_ = 0, vertex_count_ = 0;  // the two stages' invocation counts
  ComputeGrid pose_grid_, normals_grid_;  // the two stages' work groups (gl/compute_grid.h)
  GLint time_location_ = -1, stage_location_ = -1, invocation_count_location_ = -1;
};

}  // namespace glint::render
