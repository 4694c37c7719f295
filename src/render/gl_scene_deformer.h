#pragma once
// --deform-on gpu, GL's half: the scene's sine deformers as GL compute passes that pose the frame
// pipeline's vertex buffer in place (positions and smooth normals, as SineDeformer does on the CPU;
// shaders/sine_deform.comp.glsl), ordered with the raster passes by GL itself. A GPU ray tracer's
// device positions are posed apart, by cuda::GpuSceneDeformer on the tracer's stream; neither side
// waits for the other, so a deforming frame has no GL-CUDA hand-over of its own (one cost about
// 0.33 ms of an H100 frame: docs/perf.md "Deforming without a hand-over").
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "scene/sine_deformer.h"

#include <cstdint>
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
  // The object-space positions apply() posed for meshes()[k]: a buffer of vertex_count vec4s (w 0),
  // written by a shader (a copy from it needs GL_BUFFER_UPDATE_BARRIER_BIT first).
  GLuint posed_positions(std::size_t k) const { return meshes_.at(k).posed.id(); }

private:
  struct MeshBuffers {
    std::uint32_t vertex_count = 0;
    std::uint32_t triangle_count = 0;
    GlBuffer rest, indices, vertex_offsets, vertex_triangles, posed, face_normals;
    GlBuffer constants;  // the shader's MeshConstants uniform block, written once
  };
  const SceneDeformers& deformers_;
  GpuScene& scene_;
  std::vector<MeshBuffers> meshes_;  // parallel to deformers_.deformers()
  ShaderProgram program_;
};

}  // namespace glint::render
