#include "render/synthetic_gbuffer.h"

#include "gl/gl_check.h"
#include "render/render_targets.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace glint::render::testing {

int SyntheticScene::add_floor(float half_extent, vec3 lit, float reflectivity) {
  return add_quad(1, vec3(-half_extent, 0.0f, -half_extent), vec3(half_extent, 0.0f, half_extent),
                  vec3(0.0f, 1.0f, 0.0f), lit, reflectivity);
}

int SyntheticScene::add_box(vec3 min, vec3 max, vec3 lit, float reflectivity) {
  const int object = next_object_++;
  for (int axis = 0; axis < 3; ++axis) {
    for (const float side : {-1.0f, 1.0f}) {
      SyntheticQuad quad;
      quad.axis = axis;
      quad.min = min;
      quad.max = max;
      quad.min[axis] = quad.max[axis] = side < 0.0f ? min[axis] : max[axis];
      quad.normal = vec3(0.0f);
      quad.normal[axis] = side;
      quad.lit = lit;
      quad.reflectivity = reflectivity;
      quad.object = object;
      quads.push_back(quad);
    }
  }
  return object;
}

int SyntheticScene::add_quad(int axis, vec3 min, vec3 max, vec3 normal, vec3 lit, float reflectivity) {
  SyntheticQuad quad;
  quad.axis = axis;
  quad.min = min;
  quad.max = max;
  quad.normal = normal;
  quad.lit = lit;
  quad.reflectivity = reflectivity;
  quad.object = next_object_++;
  quads.push_back(quad);
  return quad.object;
}

std::optional<SurfaceHit> trace(const SyntheticScene& scene, vec3 origin, vec3 direction, float t_min) {
  std::optional<SurfaceHit> nearest;
  for (std::size_t i = 0; i < scene.quads.size(); ++i) {
    const SyntheticQuad& quad = scene.quads[i];
    const int a = quad.axis;
    if (std::abs(direction[a]) < 1e-12f) continue;
    const float t = (quad.min[a] - origin[a]) / direction[a];
    if (!(t > t_min) || (nearest && t >= nearest->t)) continue;
    const vec3 p = origin + t * direction;
    bool inside = true;
    for (int b = 0; b < 3; ++b)
      if (b != a && (p[b] < quad.min[b] || p[b] > quad.max[b])) inside = false;
    if (inside) nearest = SurfaceHit{t, static_cast<int>(i), p};
  }
  return nearest;
}

FrameConstants frame_constants_for(const SyntheticCamera& camera, int width, int height, int frame) {
  CameraState state;
  state.position = camera.position;
  state.target = camera.target;
  state.fov_y_degrees = camera.fov_y_degrees;
  FrameConstants constants;
  constants.view = state.view();
  constants.projection = glm::perspective(glm::radians(camera.fov_y_degrees),
                                          static_cast<float>(width) / static_cast<float>(height), camera.near_plane,
                                          camera.far_plane);
  constants.view_projection = constants.projection * constants.view;
  constants.inverse_view = glm::inverse(constants.view);
  constants.inverse_projection = glm::inverse(constants.projection);
  constants.camera_position = vec4(camera.position, 1.0f);
  constants.near_far = vec4(camera.near_plane, camera.far_plane, 0.0f, 0.0f);
  constants.viewport = glm::ivec4(width, height, frame, 0);
  return constants;
}

vec3 primary_ray(const FrameConstants& constants, int x, int y) {
  const vec2 ndc((static_cast<float>(x) + 0.5f) / static_cast<float>(constants.viewport.x) * 2.0f - 1.0f,
                 (static_cast<float>(y) + 0.5f) / static_cast<float>(constants.viewport.y) * 2.0f - 1.0f);
  // Through the view-space direction turned by the view's rotation (transposed: it is orthonormal),
  // not through world points or a general inverse, which lose the direction's precision when the
  // camera is far from the origin.
  const vec4 far_point = constants.inverse_projection * vec4(ndc, 1.0f, 1.0f);
  return glm::normalize(glm::transpose(glm::mat3(constants.view)) * (vec3(far_point) / far_point.w));
}

vec2 project_to_pixels(const FrameConstants& constants, vec3 world) {
  const vec4 clip = constants.view_projection * vec4(world, 1.0f);
  const vec2 ndc = vec2(clip) / clip.w;
  return (ndc * 0.5f + 0.5f) * vec2(constants.viewport.x, constants.viewport.y);
}

CpuGBuffer rasterize(const SyntheticScene& scene, const FrameConstants& constants, int width, int height) {
  CpuGBuffer g;
  g.width = width;
  g.height = height;
  const std::size_t count = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  g.albedo_reflectivity.assign(count, glm::u8vec4(0));
  g.world_position.assign(count, vec4(0.0f));
  g.world_normal.assign(count, vec4(0.0f));
  g.lit.assign(count, vec4(scene.sky, 1.0f));
  g.quad.assign(count, -1);
  g.t.assign(count, 0.0f);
  const vec3 eye(constants.camera_position);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const auto hit = trace(scene, eye, primary_ray(constants, x, y));
      if (!hit) continue;
      const SyntheticQuad& quad = scene.quads[static_cast<std::size_t>(hit->quad)];
      const std::size_t i = g.index(x, y);
      const auto to_byte = [](float v) { return static_cast<std::uint8_t>(std::lround(glm::clamp(v, 0.0f, 1.0f) * 255.0f)); };
      g.albedo_reflectivity[i] =
          glm::u8vec4(to_byte(quad.albedo.x), to_byte(quad.albedo.y), to_byte(quad.albedo.z), to_byte(quad.reflectivity));
      g.world_position[i] = vec4(hit->position, 1.0f);
      g.world_normal[i] = vec4(quad.normal, 0.0f);
      g.lit[i] = vec4(lit_at(quad, hit->position), 1.0f);
      g.quad[i] = hit->quad;
      g.t[i] = hit->t;
    }
  }
  return g;
}

namespace {

// One RGBA texture with immutable storage, filled from `texels` given as `type`.
GlTexture upload_texels(GLenum internal_format, int width, int height, GLenum type, const void* texels) {
  GlTexture texture = create_texture_2d(internal_format, width, height);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTextureSubImage2D(texture.id(), 0, 0, 0, width, height, GL_RGBA, type, texels);
  check_gl("test texture upload");
  return texture;
}

}  // namespace

GlTexture upload_rgba(GLenum internal_format, int width, int height, const std::vector<vec4>& pixels) {
  return upload_texels(internal_format, width, height, GL_FLOAT, pixels.data());
}

GlTexture upload_rgba8(int width, int height, const std::vector<glm::u8vec4>& pixels) {
  return upload_texels(GL_RGBA8, width, height, GL_UNSIGNED_BYTE, pixels.data());
}

GlTexture upload_rgba16f_bits(int width, int height, const std::vector<std::uint16_t>& halves) {
  return upload_texels(GL_RGBA16F, width, height, GL_HALF_FLOAT, halves.data());
}

GpuGBuffer upload(const CpuGBuffer& g, const FrameConstants& constants) {
  GpuGBuffer gpu;
  gpu.albedo_reflectivity = upload_rgba8(g.width, g.height, g.albedo_reflectivity);
  gpu.world_position = upload_rgba(kWorldPositionFormat, g.width, g.height, g.world_position);
  gpu.world_normal = upload_rgba(kWorldNormalRoughnessFormat, g.width, g.height, g.world_normal);
  gpu.lit = upload_rgba(kLitFormat, g.width, g.height, g.lit);
  gpu.frame_constants = create_buffer(sizeof(FrameConstants), &constants);
  return gpu;
}

namespace {

template <typename T>
std::vector<T> read_texture(GLuint texture, int width, int height, std::size_t per_pixel, GLenum format, GLenum type) {
  std::vector<T> data(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * per_pixel);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTextureImage(texture, 0, format, type, static_cast<GLsizei>(data.size() * sizeof(T)), data.data());
  check_gl("test readback");
  return data;
}

}  // namespace

std::vector<vec4> read_rgba_float(GLuint texture, int width, int height) {
  return read_texture<vec4>(texture, width, height, 1, GL_RGBA, GL_FLOAT);
}
std::vector<std::uint16_t> read_rgba16f_bits(GLuint texture, int width, int height) {
  return read_texture<std::uint16_t>(texture, width, height, 4, GL_RGBA, GL_HALF_FLOAT);
}
std::vector<glm::u8vec4> read_rgba8(GLuint texture, int width, int height) {
  return read_texture<glm::u8vec4>(texture, width, height, 1, GL_RGBA, GL_UNSIGNED_BYTE);
}
std::vector<std::uint8_t> read_r8ui(GLuint texture, int width, int height) {
  return read_texture<std::uint8_t>(texture, width, height, 1, GL_RED_INTEGER, GL_UNSIGNED_BYTE);
}

}  // namespace glint::render::testing
