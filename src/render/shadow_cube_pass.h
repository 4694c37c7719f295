#pragma once
// ShadowCubePass: omnidirectional shadow map of the point light: six draws of the scene, one per
// face, each skipping the chunks of the scene outside its frustum (shadow_chunks.h), or one layered
// draw in which a geometry shader routes each triangle to the faces it may touch (ShadowCubeDraw,
// raster_settings.h); the depths are the same either way.
//   inputs:  GpuScene, light position, world bounds of the scene (set the near distance)
//   outputs: cube_map(): GL_DEPTH_COMPONENT32F cube, size x size per face, nearest filtering,
//            holding near_distance() / m, m the distance from the light along the face's axis (the
//            largest coordinate of p - light), 0 where nothing is: reversed depth, written by the
//            rasteriser itself. A fragment shader that wrote a distance (gl_FragDepth) would turn
//            off the early depth test; with it the pass took twice as long at 1024^2 faces on the
//            H100. cube_shadow.glsl turns the depth back into a distance along any direction.
// No face culling: the scenes are open, single-sided sheets (a floor, a banner), and culling either
// side would let light through them; ShadowMaskPass's bias and normal offset handle acne instead.
#include "core/math.h"
#include "gl/gl_objects.h"
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/raster_settings.h"
#include "render/shadow_chunks.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace glint::render {

// The six view-projection matrices of a cube map's faces seen from `light` (GL face order +X, -X,
// +Y, -Y, +Z, -Z, with the cube-map convention's up vectors), 90-degree perspective with reversed
// depth and no far plane, for glClipControl's [0, 1] clip depth: depth = near_distance / m.
std::array<mat4, 6> cube_face_view_projections(vec3 light, float near_distance);

class ShadowCubePass {
public:
  // Throws glint::Error for a size beyond GL_MAX_CUBE_MAP_TEXTURE_SIZE.
  explicit ShadowCubePass(int size = 1024, ShadowCubeDraw draw = ShadowCubeDraw::per_face);

  // `chunks`, when given (made from the same scene), lets the per-face draw skip the chunks whose
  // world box lies outside a face's frustum; without them every face draws every instance. The
  // layered draw ignores them.
  void run(const GpuScene& scene, vec3 light_position, const Aabb& world_bounds, const ShadowChunks* chunks = nullptr);

  GLuint cube_map() const { return cube_map_.id(); }
  int size() const { return size_; }
  float near_distance() const { return near_distance_; }  // of the last run: depth d stands for near / d
  ShadowCubeDraw draw() const { return draw_; }
  // Draw commands (chunks, or instances without chunks) of each face in the last per-face run.
  const std::array<std::uint32_t, 6>& face_draw_counts() const { return face_draw_counts_; }

private:
  void draw_layered(const GpuScene& scene, const std::array<mat4, 6>& faces);
  void draw_per_face(const GpuScene& scene, const std::array<mat4, 6>& faces, const ShadowChunks* chunks, vec3 light);

  int size_;
  ShadowCubeDraw draw_;
  float near_distance_ = 1.0f;
  GlTexture cube_map_;
  GlFramebuffer framebuffer_;                   // all six faces (layered): cleared, and the layered draw
  std::array<GlFramebuffer, 6> face_framebuffers_;  // one face each (per_face)
  // per_face: each face's draw commands, face f's from f * (chunk or instance count) on.
  std::vector<DrawElementsIndirectCommand> face_commands_;
  GlBuffer face_command_buffer_;
  std::size_t face_command_bytes_ = 0;
  std::array<std::uint32_t, 6> face_draw_counts_{};
  ShaderProgram program_;
};

// Sets the cube-shadow settings of a program that calls cube_shadow_visibility (near_distance,
// texel_angle, pcf_radius_texels and the three biases, from the last run of `cube` and `settings`):
// one place for what ShadowMaskPass and HitShadingPass each set, so their shadows cannot drift apart.
void set_cube_shadow_uniforms(ShaderProgram& program, const ShadowCubePass& cube, const RasterSettings& settings);

}  // namespace glint::render
