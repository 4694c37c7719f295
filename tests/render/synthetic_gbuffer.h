#pragma once
// Analytic G-buffers for testing the screen-space passes without the raster passes: a scene of
// axis-aligned rectangles (a floor, boxes, one-sided walls), ray cast on the CPU through every pixel
// centre of a camera, uploaded in the formats of render_targets.h. The same ray caster answers
// where a mirror ray really goes, which is what the SSR tests compare against.
#include "core/math.h"
#include "gl/gl_objects.h"
#include "render/frame_constants.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <vector>

namespace glint::render::testing {

// An axis-aligned rectangle: min[axis] == max[axis] is its plane, the other two axes its extent.
// Visible from both sides; `normal` is the authored normal (G-buffer normals are never flipped).
struct SyntheticQuad {
  int axis = 1;
  vec3 min{0.0f};
  vec3 max{0.0f};
  vec3 normal{0.0f, 1.0f, 0.0f};
  vec3 lit{0.0f};     // radiance the lighting pass would have produced
  vec3 lit_per_x{0.0f};  // its change per world unit along x (a shading gradient across the quad)
  vec3 albedo{0.5f};
  float reflectivity = 0.0f;
  int object = 0;     // quads of one box share an object id
};

struct SyntheticScene {
  std::vector<SyntheticQuad> quads;
  vec3 sky{0.3f, 0.5f, 0.8f};  // lit colour of background pixels

  // The plane y = 0 for |x|, |z| <= half_extent, normal +y. Returns its object id.
  int add_floor(float half_extent, vec3 lit, float reflectivity);
  // Six outward-facing rectangles. Returns the box's object id.
  int add_box(vec3 min, vec3 max, vec3 lit, float reflectivity);
  // One rectangle in the plane axis = min[axis], authored normal `normal`. Returns its object id.
  int add_quad(int axis, vec3 min, vec3 max, vec3 normal, vec3 lit, float reflectivity);

private:
  int next_object_ = 0;
};

// The lit colour of `quad` at world point `p` (lit + lit_per_x * p.x).
inline vec3 lit_at(const SyntheticQuad& quad, vec3 p) { return quad.lit + quad.lit_per_x * p.x; }

struct SurfaceHit {
  float t = 0.0f;
  int quad = -1;
  vec3 position{0.0f};
};

// Nearest rectangle along origin + t * direction with t > t_min.
std::optional<SurfaceHit> trace(const SyntheticScene& scene, vec3 origin, vec3 direction, float t_min = 1e-4f);

struct SyntheticCamera {
  vec3 position{0.0f, 1.5f, 4.0f};
  vec3 target{0.0f, 0.5f, 0.0f};
  float fov_y_degrees = 60.0f;
  float near_plane = 0.05f;
  float far_plane = 200.0f;
};

// The same constants make_frame_constants builds (GL perspective, look-at view), for this camera.
FrameConstants frame_constants_for(const SyntheticCamera& camera, int width, int height, int frame = 0);

// Unit direction of the primary ray through the centre of pixel (x, y), y = 0 the bottom row.
vec3 primary_ray(const FrameConstants& constants, int x, int y);

// Pixel position (x right, y up, pixel centres at +0.5) where a world point projects.
vec2 project_to_pixels(const FrameConstants& constants, vec3 world);

// Per-pixel CPU G-buffer, rows bottom first (GL order): index y * width + x.
struct CpuGBuffer {
  int width = 0;
  int height = 0;
  std::vector<glm::u8vec4> albedo_reflectivity;
  std::vector<vec4> world_position;
  std::vector<vec4> world_normal;
  std::vector<vec4> lit;
  std::vector<int> quad;  // visible quad, -1 background
  std::vector<float> t;   // primary-ray distance, 0 background

  std::size_t index(int x, int y) const { return static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x); }
};

CpuGBuffer rasterize(const SyntheticScene& scene, const FrameConstants& constants, int width, int height);

struct GpuGBuffer {
  GlTexture albedo_reflectivity;
  GlTexture world_position;
  GlTexture world_normal;
  GlTexture lit;
  GlBuffer frame_constants;
};

GpuGBuffer upload(const CpuGBuffer& gbuffer, const FrameConstants& constants);

// Texture upload / readback helpers (rows bottom first, tightly packed).
GlTexture upload_rgba(GLenum internal_format, int width, int height, const std::vector<vec4>& pixels);
GlTexture upload_rgba8(int width, int height, const std::vector<glm::u8vec4>& pixels);
GlTexture upload_rgba16f_bits(int width, int height, const std::vector<std::uint16_t>& halves);
std::vector<vec4> read_rgba_float(GLuint texture, int width, int height);
std::vector<std::uint16_t> read_rgba16f_bits(GLuint texture, int width, int height);
std::vector<glm::u8vec4> read_rgba8(GLuint texture, int width, int height);
std::vector<std::uint8_t> read_r8ui(GLuint texture, int width, int height);

}  // namespace glint::render::testing
