#pragma once
// ShadowCubePass: omnidirectional shadow map of the point light, all six faces in one layered draw
// (a geometry shader routes each triangle to the faces it touches).
//   inputs:  GpuScene, light position, world bounds of the scene (sets the far distance)
//   outputs: cube_map(): GL_DEPTH_COMPONENT32F cube, size x size per face, holding
//            distance to the light / far_distance() (1 = nothing within far), nearest filtering
// No face culling: the scenes are open, single-sided sheets (a floor, a banner), and culling either
// side would let light through them; ShadowMaskPass's bias and normal offset handle acne instead.
#include "core/math.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"

#include <array>

namespace glint::render {

// The six view-projection matrices of a cube map's faces seen from `light` (GL face order +X, -X,
// +Y, -Y, +Z, -Z, with the cube-map convention's up vectors), 90-degree perspective.
std::array<mat4, 6> cube_face_view_projections(vec3 light, float near_distance, float far_distance);

class ShadowCubePass {
public:
  explicit ShadowCubePass(int size = 1024);  // throws glint::Error beyond GL_MAX_CUBE_MAP_TEXTURE_SIZE

  void run(const GpuScene& scene, vec3 light_position, const Aabb& world_bounds);

  GLuint cube_map() const { return cube_map_.id(); }
  int size() const { return size_; }
  float far_distance() const { return far_distance_; }  // of the last run

private:
  int size_;
  float far_distance_ = 1.0f;
  GlTexture cube_map_;
  GlFramebuffer framebuffer_;
  ShaderProgram program_;
};

}  // namespace glint::render
