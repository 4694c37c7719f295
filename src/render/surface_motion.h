#pragma once
// SurfaceMotion: how far each pixel's surface point moved since the previous frame by itself, for
// the denoiser's reprojection of the deforming meshes (docs/glossy.md, "Motion of the deforming
// meshes"). The camera's motion is not in it: the denoiser projects the previous world position
// with the previous frame's view-projection.
//   previous vertices  a copy of the GpuScene's vertex buffer as the last G-buffer read it (std430
//                      GpuVertex[] at kPreviousVertexBufferBinding, include/surface_motion.glsl);
//                      keep_vertices() refreshes the deforming meshes' ranges after each G-buffer
//   world_motion       (kWorldMotionFormat) xyz = previous - current world position of the pixel's
//                      surface point, w = 0; written by both G-buffer methods (gbuffer.vert/frag and
//                      include/visibility_gbuffer_main.glsl): each corner's displacement
//                      mat3(model) * (previous - current object position), interpolated with the
//                      pixel's weights. A static vertex's difference is exactly 0, so static geometry
//                      (and every pixel of a scene that does not deform) gets exactly 0.
// Made only when RasterSettings::surface_motion is on (the frame pipeline turns it on with
// --denoise on): the other frames write no extra image.
#include "gl/gl_objects.h"
#include "render/gpu_scene.h"
#include "scene/scene.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <vector>

namespace glint::render {

inline constexpr GLenum kWorldMotionFormat = GL_RGBA16F;
inline constexpr GLuint kPreviousVertexBufferBinding = 29;
inline constexpr GLuint kMovingMeshBinding = 30;  // uint per mesh: 1 deforms, 0 static

class SurfaceMotion {
public:
  // The previous vertices start as `gpu_scene`'s current ones (no motion on the first frame).
  SurfaceMotion(const Scene& scene, const GpuScene& gpu_scene, int width, int height);

  // Binds the previous vertices and the per-mesh moving flags (static meshes skip the vertex reads).
  void bind_previous_vertices() const;
  // This frame's vertices become the next frame's previous ones: a GPU copy of the deforming meshes'
  // ranges (none for a static scene). Call after the G-buffer pass.
  void keep_vertices(const GpuScene& gpu_scene);

  GLuint world_motion() const { return world_motion_.id(); }

private:
  GlTexture world_motion_;
  GlBuffer previous_vertices_;
  GlBuffer moving_mesh_flags_;
  std::vector<std::uint32_t> moving_meshes_;
};

}  // namespace glint::render
