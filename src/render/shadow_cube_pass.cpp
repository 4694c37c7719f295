#include "render/shadow_cube_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>

namespace glint::render {

std::array<mat4, 6> cube_face_view_projections(vec3 light, float near_distance, float far_distance) {
  // Cube-map faces are addressed with t growing downwards (the RenderMan convention GL inherited),
  // hence the -y up vectors for the side faces.
  static const std::array<vec3, 6> directions = {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0),
                                                 vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1)};
  static const std::array<vec3, 6> ups = {vec3(0, -1, 0), vec3(0, -1, 0), vec3(0, 0, 1),
                                          vec3(0, 0, -1), vec3(0, -1, 0), vec3(0, -1, 0)};
  const mat4 projection = glm::perspective(glm::radians(90.0f), 1.0f, near_distance, far_distance);
  std::array<mat4, 6> result;
  for (std::size_t face = 0; face < 6; ++face)
    result[face] = projection * glm::lookAt(light, light + directions[face], ups[face]);
  return result;
}

ShadowCubePass::ShadowCubePass(int size)
    : size_(size), program_(ShaderProgram::from_embedded(
                       {"shadow_cube.vert.glsl", "shadow_cube.geom.glsl", "shadow_cube.frag.glsl"})) {
  GLint max_size = 0;
  glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &max_size);
  if (size < 1 || size > max_size) fail("shadow cube map: size {} is outside 1..{}", size, max_size);
  cube_map_ = create_texture_cube(GL_DEPTH_COMPONENT32F, size);
  const GLuint id = cube_map_.id();
  glTextureParameteri(id, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(id, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(id, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  framebuffer_ = create_framebuffer();
  glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, id, 0);  // layered: all six faces
  glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
  require_framebuffer_complete(framebuffer_, "shadow cube map");
  check_gl("shadow cube pass set-up");
}

void ShadowCubePass::run(const GpuScene& scene, vec3 light_position, const Aabb& world_bounds) {
  GlPassScope scope("shadow_cube");
  // Far: the farthest corner of the scene's box from the light (plus a margin for deforming
  // meshes), so every receiver's distance fits in 0..1.
  float farthest = 1.0f;
  if (!world_bounds.empty())
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 p((corner & 1) ? world_bounds.max.x : world_bounds.min.x,
                   (corner & 2) ? world_bounds.max.y : world_bounds.min.y,
                   (corner & 4) ? world_bounds.max.z : world_bounds.min.z);
      farthest = std::max(farthest, glm::length(p - light_position));
    }
  far_distance_ = farthest * 1.1f;
  const float near_distance = far_distance_ * 1e-5f;
  const std::array<mat4, 6> faces = cube_face_view_projections(light_position, near_distance, far_distance_);
  for (int face = 0; face < 6; ++face) {
    std::string name = "face_view_projection[";
    name += std::to_string(face);
    name += ']';
    program_.set_uniform(name, faces[static_cast<std::size_t>(face)]);
  }
  program_.set_uniform("light_position", light_position);
  program_.set_uniform("inverse_far_distance", 1.0f / far_distance_);

  const float cleared = 1.0f;
  glDepthMask(GL_TRUE);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &cleared);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDisable(GL_CULL_FACE);
  program_.use();
  scene.draw_all_instances();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  check_gl("shadow cube pass");
}

}  // namespace glint::render
