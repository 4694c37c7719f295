#include "render/shadow_cube_pass.h"

#include "core/error.h"
#include "gl/gl_check.h"
#include "gl/gl_pass_scope.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <string>

namespace glint::render {

std::array<mat4, 6> cube_face_view_projections(vec3 light, float near_distance) {
  // Cube-map faces are addressed with t growing downwards (the RenderMan convention GL inherited),
  // hence the -y up vectors for the side faces.
  static const std::array<vec3, 6> directions = {vec3(1, 0, 0), vec3(-1, 0, 0), vec3(0, 1, 0),
                                                 vec3(0, -1, 0), vec3(0, 0, 1), vec3(0, 0, -1)};
  static const std::array<vec3, 6> ups = {vec3(0, -1, 0), vec3(0, -1, 0), vec3(0, 0, 1),
                                          vec3(0, 0, -1), vec3(0, -1, 0), vec3(0, -1, 0)};
  // 90 degrees, reversed depth with no far plane, for clip depth in [0, 1] (glClipControl): clip
  // z = near and w = m, the distance along the face's axis, so the stored depth is near / m.
  mat4 projection(0.0f);
  projection[0][0] = 1.0f;
  projection[1][1] = 1.0f;
  projection[2][3] = -1.0f;
  projection[3][2] = near_distance;
  std::array<mat4, 6> result;
  for (std::size_t face = 0; face < 6; ++face)
    result[face] = projection * glm::lookAt(light, light + directions[face], ups[face]);
  return result;
}

namespace {

// Whether `box` may reach into the frustum of `view_projection`: false when all eight corners are
// outside one clip plane (-w <= x, y, z <= w). Each plane is a half-space of world space (clip
// coordinates are linear in the point), so the whole box is outside with its corners: exact for
// culling, never drops anything visible.
bool box_may_be_in_frustum(const Aabb& box, const mat4& view_projection) {
  std::array<vec4, 8> clip;
  for (int corner = 0; corner < 8; ++corner) {
    const vec3 p((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                 (corner & 4) ? box.max.z : box.min.z);
    clip[static_cast<std::size_t>(corner)] = view_projection * vec4(p, 1.0f);
  }
  for (int axis = 0; axis < 3; ++axis) {
    bool all_above = true, all_below = true;
    for (const vec4& c : clip) {
      all_above = all_above && c[axis] > c.w;
      all_below = all_below && c[axis] < -c.w;
    }
    if (all_above || all_below) return false;
  }
  return true;
}

// `box` moved by -light (the faces look from the origin), widened by a few float steps of its
// coordinates so that the rounded subtraction never shrinks it: culling stays conservative.
Aabb light_relative(const Aabb& box, vec3 light) {
  const vec3 slack = 2e-7f * box.largest_abs() + 2e-7f * glm::abs(light);
  return Aabb{box.min - light - slack, box.max - light + slack};
}

ShaderProgram shadow_program(ShadowCubeDraw draw) {
  if (draw == ShadowCubeDraw::layered)
    return ShaderProgram::from_embedded({"shadow_cube.vert.glsl", "shadow_cube.geom.glsl", "shadow_cube.frag.glsl"});
  return ShaderProgram::from_embedded({"shadow_cube_face.vert.glsl", "shadow_cube.frag.glsl"});
}

}  // namespace

ShadowCubePass::ShadowCubePass(int size, ShadowCubeDraw draw)
    : size_(size), draw_(draw), program_(shadow_program(draw)) {
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
  if (draw_ == ShadowCubeDraw::per_face)
    for (int face = 0; face < 6; ++face) {
      GlFramebuffer& framebuffer = face_framebuffers_[static_cast<std::size_t>(face)];
      framebuffer = create_framebuffer();
      glNamedFramebufferTextureLayer(framebuffer.id(), GL_DEPTH_ATTACHMENT, id, 0, face);
      glNamedFramebufferDrawBuffer(framebuffer.id(), GL_NONE);
      require_framebuffer_complete(framebuffer, "shadow cube map face");
    }
  check_gl("shadow cube pass set-up");
}

void ShadowCubePass::run(const GpuScene& scene, vec3 light_position, const Aabb& world_bounds,
                         const ShadowChunks* chunks) {
  GlPassScope scope("shadow_cube");
  // Near: a tiny fraction of the distance to the farthest corner of the scene's box, so nothing
  // in the scene is clipped; reversed float depth keeps the same relative precision at any distance.
  float farthest = 1.0f;
  if (!world_bounds.empty())
    for (int corner = 0; corner < 8; ++corner) {
      const vec3 p((corner & 1) ? world_bounds.max.x : world_bounds.min.x,
                   (corner & 2) ? world_bounds.max.y : world_bounds.min.y,
                   (corner & 4) ? world_bounds.max.z : world_bounds.min.z);
      farthest = std::max(farthest, glm::length(p - light_position));
    }
  near_distance_ = farthest * 1e-5f;
  // Light-relative: the faces look from the origin and the vertex shaders subtract the light, so a
  // scene far from the origin gets the depths it gets at the origin (docs/render.md).
  const std::array<mat4, 6> faces = cube_face_view_projections(vec3(0.0f), near_distance_);
  program_.set_uniform("light_origin", light_position);

  // Reversed depth: 0 is "nothing", nearer is larger. Clip depth [0, 1] only for this pass; the
  // other passes keep GL's default [-1, 1].
  const float cleared = 0.0f;
  glDepthMask(GL_TRUE);
  glClearNamedFramebufferfv(framebuffer_.id(), GL_DEPTH, 0, &cleared);  // all six faces
  glViewport(0, 0, size_, size_);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_GREATER);
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDisable(GL_CULL_FACE);
  program_.use();
  if (draw_ == ShadowCubeDraw::layered)
    draw_layered(scene, faces);
  else
    draw_per_face(scene, faces, chunks, light_position);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glDepthFunc(GL_LESS);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
  check_gl("shadow cube pass");
}

void ShadowCubePass::draw_layered(const GpuScene& scene, const std::array<mat4, 6>& faces) {
  for (int face = 0; face < 6; ++face) {
    std::string name = "face_view_projection[";
    name += std::to_string(face);
    name += ']';
    program_.set_uniform(name, faces[static_cast<std::size_t>(face)]);
  }
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  scene.draw_all_instances();
}

void ShadowCubePass::draw_per_face(const GpuScene& scene, const std::array<mat4, 6>& faces,
                                   const ShadowChunks* chunks, vec3 light) {
  // Each face's commands: the chunks that may touch it (or every instance), in order. One upload
  // per run into a buffer made once.
  const std::size_t candidates = chunks != nullptr ? chunks->chunks().size() : scene.draw_command_data().size();
  face_commands_.resize(6 * candidates);
  for (std::size_t face = 0; face < 6; ++face) {
    DrawElementsIndirectCommand* out = face_commands_.data() + face * candidates;
    std::uint32_t count = 0;
    if (chunks == nullptr) {
      for (const DrawElementsIndirectCommand& command : scene.draw_command_data()) out[count++] = command;
    } else {
      for (const ShadowChunk& chunk : chunks->chunks())
        if (!chunk.world_box || box_may_be_in_frustum(light_relative(*chunk.world_box, light), faces[face]))
          out[count++] = chunk.command;
    }
    face_draw_counts_[face] = count;
  }
  const std::size_t bytes = face_commands_.size() * sizeof(DrawElementsIndirectCommand);
  if (bytes == 0) return;
  if (face_command_bytes_ < bytes) {
    face_command_buffer_ = create_buffer(bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    face_command_bytes_ = bytes;
  }
  glNamedBufferSubData(face_command_buffer_.id(), 0, static_cast<GLsizeiptr>(bytes), face_commands_.data());
  const GLuint index_buffer = chunks != nullptr ? chunks->index_buffer() : 0;
  for (std::size_t face = 0; face < 6; ++face) {
    program_.set_uniform("face_view_projection", faces[face]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, face_framebuffers_[face].id());
    scene.draw_commands(face_command_buffer_.id(), face * candidates, face_draw_counts_[face], index_buffer);
  }
}

// The includers (shadow_mask.comp.glsl, hit_shading.comp.glsl) declare these uniforms under these
// names and pass them on as the CubeShadowSettings of shaders/include/cube_shadow.glsl, which
// declares no uniforms itself.
void set_cube_shadow_uniforms(ShaderProgram& program, const ShadowCubePass& cube, const RasterSettings& settings) {
  program.set_uniform("near_distance", cube.near_distance());
  program.set_uniform("texel_angle", 2.0f / static_cast<float>(cube.size()));
  program.set_uniform("pcf_radius_texels", settings.pcf_radius_texels);
  program.set_uniform("constant_bias_texels", settings.constant_bias_texels);
  program.set_uniform("slope_bias_texels", settings.slope_bias_texels);
  program.set_uniform("normal_offset_texels", settings.normal_offset_texels);
}

}  // namespace glint::render
