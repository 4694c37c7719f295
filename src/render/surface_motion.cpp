#include "render/surface_motion.h"

#include "core/error.h"
#include "gl/gl_check.h"

#include <cstddef>
#include <span>

namespace glint::render {

SurfaceMotion::SurfaceMotion(const Scene& scene, const GpuScene& gpu_scene, int width, int height)
    : moving_meshes_(scene.deformable_meshes()) {
  if (width <= 0 || height <= 0) fail("surface motion: invalid size {}x{}", width, height);
  world_motion_ = create_texture_2d(kWorldMotionFormat, width, height);
  glTextureParameteri(world_motion_.id(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(world_motion_.id(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const auto bytes = static_cast<GLsizeiptr>(gpu_scene.vertex_count() * sizeof(GpuVertex));
  previous_vertices_ = create_buffer(static_cast<std::size_t>(bytes), nullptr, 0);
  glCopyNamedBufferSubData(gpu_scene.vertex_buffer(), previous_vertices_.id(), 0, 0, bytes);
  std::vector<std::uint32_t> flags(gpu_scene.mesh_ranges().size(), 0u);
  for (const std::uint32_t mesh : moving_meshes_) flags.at(mesh) = 1u;
  moving_mesh_flags_ = create_buffer(std::span<const std::uint32_t>(flags));
  check_gl("surface motion: set-up");
}

void SurfaceMotion::bind_previous_vertices() const {
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPreviousVertexBufferBinding, previous_vertices_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMovingMeshBinding, moving_mesh_flags_.id());
}

void SurfaceMotion::keep_vertices(const GpuScene& gpu_scene) {
  for (const std::uint32_t mesh : moving_meshes_) {
    const GpuMeshRange& range = gpu_scene.mesh_ranges().at(mesh);
    const auto offset = static_cast<GLintptr>(range.base_vertex * sizeof(GpuVertex));
    glCopyNamedBufferSubData(gpu_scene.vertex_buffer(), previous_vertices_.id(), offset, offset,
                             static_cast<GLsizeiptr>(range.vertex_count * sizeof(GpuVertex)));
  }
  check_gl("surface motion: keeping the vertices");
}

}  // namespace glint::render
