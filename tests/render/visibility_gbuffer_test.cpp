// The visibility G-buffer (VisibilityIdPass + VisibilityGBufferPass) against the raster G-buffer
// (GBufferPass), texel for texel, on scenes built in code and on an atrium frame; and a whole frame
// made with each. Both methods draw the same triangles with an invariant gl_Position, so they keep
// the same surface at every pixel: depth and material ids must be equal exactly, and the id of each
// pixel must name the triangle the raster G-buffer's position lies on.
#include "gl/gl_test_context.h"
#include "gl/shader_program.h"
#include "metrics/rmse_psnr.h"
#include "raster_test_scene.h"
#include "render/frame_pipeline.h"
#include "render/raster_pipeline.h"
#include "render/visibility_id_pass.h"
#include "scene/camera_path.h"
#include "scene/presets.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

namespace glint {
namespace {

using render::GBufferMethod;
using render::RasterOutput;
using render::RasterPipeline;
using render::RasterSettings;
using VisibilityGBuffer = testing::GlTest;

struct GBufferImages {
  ImageRgbaF albedo, position, normal, material, depth;
  std::vector<glm::uvec2> ids;  // visibility method only
  render::FrameConstants constants;
};

GBufferImages render_gbuffer(const Scene& scene, const FrameState& frame, int width, int height, GBufferMethod method) {
  RasterSettings settings;
  settings.gbuffer = method;
  RasterPipeline raster(scene, width, height, settings);
  raster.render(frame);
  GBufferImages images{raster.read_rgbaf(RasterOutput::AlbedoReflectivity),
                       raster.read_rgbaf(RasterOutput::WorldPosition),
                       raster.read_rgbaf(RasterOutput::WorldNormalRoughness),
                       raster.read_rgbaf(RasterOutput::MaterialId),
                       raster.read_rgbaf(RasterOutput::Depth),
                       {},
                       raster.frame_constants()};
  if (method == GBufferMethod::visibility) images.ids = render::read_visibility_ids(raster.visibility_id(), width, height);
  return images;
}

vec3 closest_on_segment(vec3 p, vec3 a, vec3 b) {
  const vec3 ab = b - a;
  const float t = glm::clamp(glm::dot(p - a, ab) / std::max(glm::dot(ab, ab), 1e-30f), 0.0f, 1.0f);
  return a + t * ab;
}

// Distance from `p` to the triangle abc (inside: to its plane; outside: to its nearest edge).
// Distances rather than barycentrics: the atrium has slivers, whose barycentrics are ill-conditioned.
float distance_to_triangle(vec3 p, vec3 a, vec3 b, vec3 c) {
  const float to_edges = std::min({glm::length(p - closest_on_segment(p, a, b)),
                                  glm::length(p - closest_on_segment(p, b, c)),
                                  glm::length(p - closest_on_segment(p, c, a))});
  const vec3 n = glm::normalize(glm::cross(b - a, c - a));
  const vec3 q = p - glm::dot(p - a, n) * n;  // p projected onto the plane
  const bool inside = glm::dot(glm::cross(b - a, q - a), n) >= 0.0f && glm::dot(glm::cross(c - b, q - b), n) >= 0.0f &&
                      glm::dot(glm::cross(a - c, q - c), n) >= 0.0f;
  // The edges' distance bounds the true one: a sliver's plane (its normal) is only roughly known.
  return inside ? std::min(std::abs(glm::dot(p - a, n)), to_edges) : to_edges;
}

// Tolerances. The rasteriser evaluates its interpolants at the pixel centre relative to the
// triangle as snapped to its sub-pixel grid (1/256 pixel on NVIDIA GPUs), the compute resolve at the
// exact centre: on a surface seen at a grazing angle the two points are a hair apart on screen but
// far apart in world units (measured on an H100, 2026-11-25: up to 1.2e-4 of the atrium's extent).
// So positions must lie on the triangle the id names (within 1e-5 of the scene's bounding-box
// diagonal, a few ulps of the coordinates, or at a centre the triangle covers: triangle_covers_pixel)
// and project within kScreenTolerancePixels of each other; normals,
// stored as half floats (about 1e-3 steps near 1), may differ by kNormalTolerance plus what the
// triangle's interpolated normal changes over the distance between the two points.
constexpr float kRelativePositionTolerance = 1e-5f;
constexpr float kScreenTolerancePixels = 1.0f / 32.0f;
constexpr float kNormalTolerance = 2e-3f;

// Pixel coordinates (top row 0, pixel centres at whole numbers) of a world point; nullopt behind
// the camera.
std::optional<vec2> to_screen(const render::FrameConstants& constants, vec3 world) {
  const vec4 clip = constants.view_projection * vec4(world, 1.0f);
  if (clip.w <= 0.0f) return std::nullopt;
  const vec2 ndc = vec2(clip) / clip.w;
  return vec2((ndc.x * 0.5f + 0.5f) * static_cast<float>(constants.viewport.x) - 0.5f,
              (0.5f - ndc.y * 0.5f) * static_cast<float>(constants.viewport.y) - 0.5f);
}

// How fast the triangle's interpolated world normal turns per world unit: the largest change
// between two corners over their distance (normals interpolate linearly between the corners).
float normal_change_per_unit(const Mesh& mesh, const Instance& instance, std::uint32_t triangle, const vec3 corner[3]) {
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(instance.transform)));
  vec3 normal[3];
  for (int i = 0; i < 3; ++i)
    normal[i] = glm::normalize(normal_matrix * mesh.normals[mesh.indices[3u * triangle + static_cast<unsigned>(i)]]);
  float rate = 0.0f;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    rate = std::max(rate, glm::length(normal[i] - normal[j]) / std::max(glm::length(corner[i] - corner[j]), 1e-30f));
  }
  return rate;
}

// 2D distance from `point` to the triangle `corner` (pixel units).
float distance_to_triangle_2d(vec2 point, const vec2 corner[3]) {
  const auto cross2 = [](vec2 u, vec2 v) { return u.x * v.y - u.y * v.x; };
  const float area = cross2(corner[1] - corner[0], corner[2] - corner[0]);
  bool inside = true;
  float to_edges = 1e30f;
  for (int i = 0; i < 3; ++i) {
    const vec2 a = corner[i], b = corner[(i + 1) % 3];
    inside = inside && cross2(b - a, point - a) * area >= 0.0f;
    const float t = glm::clamp(glm::dot(point - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-30f), 0.0f, 1.0f);
    to_edges = std::min(to_edges, glm::length(point - (a + t * (b - a))));
  }
  return inside ? 0.0f : to_edges;
}

// Whether the triangle (world corners) is the one the rasteriser drew at pixel (x, y, top row 0):
// the raster G-buffer's position `p` lies on it, or, when its corners are all in front of the
// camera, its projection covers the pixel centre up to 1/64 pixel (the rasteriser snaps corners to
// a sub-pixel grid, so a centre a hair outside an edge can still be covered).
bool triangle_covers_pixel(const render::FrameConstants& constants, int x, int y, vec3 p, const vec3 corner[3],
                           float extent) {
  if (distance_to_triangle(p, corner[0], corner[1], corner[2]) <= kRelativePositionTolerance * extent) return true;
  vec2 screen[3];
  for (int i = 0; i < 3; ++i) {
    const std::optional<vec2> at = to_screen(constants, corner[i]);
    if (!at) return false;
    screen[i] = *at;
  }
  return distance_to_triangle_2d(vec2(static_cast<float>(x), static_cast<float>(y)), screen) <= 1.0f / 64.0f;
}

struct Mismatches {
  int geometry = 0;           // pixels with a surface (raster material id > 0)
  int textured = 0;           // of those, with a textured material
  int depth = 0;              // depth not bit-equal
  int material = 0;           // material id not equal
  int background_id = 0;      // id 0 where there is geometry, or an id on the background
  int off_triangle = 0;       // raster position not on the triangle the id names
  int position = 0;           // position off the triangle, or not where the raster one is on screen
  int normal = 0;             // |normal difference| beyond what the positions' distance explains
  int parameters = 0;         // reflectivity or roughness not equal
  int untextured_albedo = 0;  // untextured albedo not bit-equal
  int textured_albedo = 0;    // textured albedo off by more than 2/255 in a channel
  float worst_textured_albedo = 0.0f;
  double textured_albedo_error = 0.0;  // mean over textured pixels of the largest channel difference
  float worst_position = 0.0f;  // relative to the scene's extent
  float worst_normal = 0.0f;
};


Mismatches compare(const Scene& scene, const GBufferImages& raster, const GBufferImages& visibility) {
  Mismatches m;
  const Aabb bounds = scene.world_bounds();
  const float extent = glm::length(bounds.max - bounds.min);
  const int width = raster.albedo.width, height = raster.albedo.height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const glm::uvec2 id = visibility.ids[static_cast<std::size_t>(y * width + x)];
      const float material_id = raster.material.at(x, y).x;
      m.depth += raster.depth.at(x, y).x != visibility.depth.at(x, y).x;
      m.material += material_id != visibility.material.at(x, y).x;
      if (material_id == 0.0f) {
        m.background_id += id.x != 0u;
        m.position += visibility.position.at(x, y) != vec4(0.0f);
        m.untextured_albedo += visibility.albedo.at(x, y) != vec4(0.0f);
        continue;
      }
      ++m.geometry;
      if (id.x == 0u || id.x > scene.instances.size()) {
        ++m.background_id;
        continue;
      }
      const Instance& instance = scene.instances[id.x - 1u];
      const Mesh& mesh = scene.meshes[instance.mesh];
      const vec4 p = raster.position.at(x, y);
      const vec4 q = visibility.position.at(x, y);
      const vec4 n = raster.normal.at(x, y), nv = visibility.normal.at(x, y);
      const float position_error = glm::length(vec3(p) - vec3(q)) / extent;
      const float normal_error = glm::length(vec3(n) - vec3(nv));
      m.worst_position = std::max(m.worst_position, position_error);
      m.worst_normal = std::max(m.worst_normal, normal_error);
      if (3u * id.y + 2u >= mesh.indices.size()) {
        ++m.off_triangle;
        ++m.position;
        ++m.normal;
      } else {
        vec3 corner[3];
        for (int i = 0; i < 3; ++i)
          corner[i] = vec3(instance.transform * vec4(mesh.positions[mesh.indices[3u * id.y + static_cast<unsigned>(i)]], 1.0f));
        m.off_triangle += !triangle_covers_pixel(raster.constants, x, y, vec3(p), corner, extent);
        const std::optional<vec2> p_screen = to_screen(raster.constants, vec3(p));
        const std::optional<vec2> q_screen = to_screen(raster.constants, vec3(q));
        const bool on_triangle = triangle_covers_pixel(raster.constants, x, y, vec3(q), corner, extent);
        const bool same_on_screen = p_screen && q_screen && glm::length(*p_screen - *q_screen) <= kScreenTolerancePixels;
        m.position += !on_triangle || !same_on_screen || q.w != 1.0f;
        // Twice the linear rate: normalising the interpolated normal can stretch its change a little.
        const float normal_slack = 2.0f * normal_change_per_unit(mesh, instance, id.y, corner) * glm::length(vec3(p) - vec3(q));
        m.normal += normal_error > kNormalTolerance + normal_slack;
      }
      const vec4 a = raster.albedo.at(x, y), av = visibility.albedo.at(x, y);
      m.parameters += a.w != av.w || n.w != nv.w;
      if (scene.materials[mesh.material].diffuse_texture < 0) {
        m.untextured_albedo += vec3(a) != vec3(av);
      } else {
        ++m.textured;
        const vec3 difference = glm::abs(vec3(a) - vec3(av));
        const float worst = std::max({difference.x, difference.y, difference.z});
        m.worst_textured_albedo = std::max(m.worst_textured_albedo, worst);
        m.textured_albedo += worst > 2.5f / 255.0f;
        m.textured_albedo_error += worst;
      }
    }
  if (m.textured > 0) m.textured_albedo_error /= m.textured;
  std::printf("[ visibility ] %d geometry pixels (%d textured): worst position error %.3g of the extent, worst normal "
              "error %.3g, worst textured albedo error %.1f/255, mean %.2f/255, %d textured pixels off by more than 2/255\n",
              m.geometry, m.textured, static_cast<double>(m.worst_position), static_cast<double>(m.worst_normal),
              static_cast<double>(m.worst_textured_albedo * 255.0f), m.textured_albedo_error * 255.0, m.textured_albedo);
  if (const char* dump = std::getenv("GLINT_DUMP_VISIBILITY_ALBEDO")) {  // for looking at a failure
    for (const auto& [name, image] : {std::pair{"_raster.png", &raster.albedo}, std::pair{"_visibility.png", &visibility.albedo}}) {
      ImageRgba8 opaque = quantize_to_rgba8(*image);
      for (auto& pixel : opaque.pixels) pixel.w = 255;  // the alpha channel is the reflectivity
      write_png(std::string(dump) + name, opaque);
    }
  }
  return m;
}

// Whether GL_RENDERER is Mesa's software rasteriser, where VisibilityGBufferPass filters textures in
// the shader (see expect_equal_gbuffers).
bool software_sampler(const HeadlessGlContext& context) {
  return context.renderer().find("llvmpipe") != std::string::npos ||
         context.renderer().find("softpipe") != std::string::npos;
}

// Every mismatch count but the textured albedo's must be 0. Textured albedo:
// - On a GPU the compute pass hands textureGrad the uv differences across the pixel's 2x2 quad that
//   the fragment shader's implicit derivatives are, so the same hardware filter (trilinear, 16x
//   anisotropic) samples the same footprint; differences come from float rounding and from drivers
//   that take per-pixel (fine) rather than per-quad derivatives: mean <= 1.5/255 and at most 5% of
//   the textured pixels off by more than 2/255 (H100, 2026-11-25: mean 0.09-0.13/255, at most 23 of
//   8,733 textured pixels).
// - On llvmpipe the pass filters trilinearly in the shader (isotropic), while llvmpipe's fragment
//   shaders use its anisotropic (elliptical) filter, which no compute-shader sampling reproduces
//   (its compute textureGrad is trilinear too). Measured 2026-11-25 (Mesa 22.3.6): mean 3-4/255 on
//   the atrium, 17/255 on the instanced scene's floor at grazing angles; bound 24/255, which still
//   catches sampling the wrong place of a texture (over 80/255). Uv interpolation itself is checked
//   on every driver by TexturedQuadFacingTheCameraMatchesInsideTexelBlocks, where filters agree.
constexpr double kGpuMeanTexturedError = 1.5 / 255.0;
constexpr double kLlvmpipeMeanTexturedError = 24.0 / 255.0;

void expect_equal_gbuffers(const Mismatches& m, int expected_geometry, bool software) {
  EXPECT_GE(m.geometry, expected_geometry);
  EXPECT_EQ(m.depth, 0);
  EXPECT_EQ(m.material, 0);
  EXPECT_EQ(m.background_id, 0);
  EXPECT_EQ(m.off_triangle, 0);
  EXPECT_EQ(m.position, 0) << "worst " << m.worst_position;
  EXPECT_EQ(m.normal, 0) << "worst " << m.worst_normal;
  EXPECT_EQ(m.parameters, 0);
  EXPECT_EQ(m.untextured_albedo, 0);
  if (software) {
    EXPECT_LE(m.textured_albedo_error, kLlvmpipeMeanTexturedError);
  } else {
    EXPECT_LE(m.textured_albedo_error, kGpuMeanTexturedError);
    EXPECT_LE(m.textured_albedo, m.textured / 20) << "worst " << m.worst_textured_albedo * 255.0f << "/255";
  }
}

// A texture of 16 x 16 blocks of distinct colours: neighbouring mip levels differ, so a wrong level
// of detail changes the albedo.
Texture block_texture() {
  Texture texture;
  texture.name = "blocks";
  texture.width = texture.height = 64;
  texture.rgba.resize(64 * 64 * 4);
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 64; ++x) {
      const int bx = x / 4, by = y / 4;
      const std::uint8_t rgb[3] = {static_cast<std::uint8_t>((bx * 53 + by * 17) % 256),
                                   static_cast<std::uint8_t>((bx * 29 + by * 71) % 256),
                                   static_cast<std::uint8_t>(((bx ^ by) & 1) * 200 + 30)};
      std::uint8_t* texel = &texture.rgba[static_cast<std::size_t>((y * 64 + x) * 4)];
      for (int c = 0; c < 3; ++c) texel[c] = rgb[c];
      texel[3] = 255;
    }
  return texture;
}

// A textured floor seen at grazing angles (uv repeating 10 times: mip levels from 0 to the top),
// an untextured wall, and one textured quad mesh drawn by three instances under rotations and
// non-uniform scales (instance ids, model and normal matrices), one of them behind the wall in part.
Scene instanced_test_scene() {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 6.0f, 0.0f));
  scene.textures.push_back(block_texture());
  const std::uint32_t floor_material = testing::add_material(scene, vec3(1.0f), 0.4f, 0);
  const std::uint32_t wall_material = testing::add_material(scene, vec3(0.3f, 0.6f, 0.2f), 0.1f);
  const std::uint32_t box_material = testing::add_material(scene, vec3(0.9f, 0.8f, 1.0f), 0.0f, 0);
  const std::uint32_t floor =
      testing::add_quad(scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), floor_material);
  for (vec2& uv : scene.meshes[floor].uvs) uv *= 10.0f;
  testing::add_quad(scene, vec3(-4.0f, 0.0f, -6.0f), vec3(8.0f, 0.0f, 0.0f), vec3(0.0f, 3.0f, 0.0f), wall_material);
  const std::uint32_t quad =
      testing::add_quad(scene, vec3(-1.0f, -1.0f, 0.0f), vec3(2.0f, 0.0f, 0.0f), vec3(0.0f, 2.0f, 0.0f), box_material);
  const mat4 transforms[3] = {
      glm::translate(mat4(1.0f), vec3(-2.0f, 1.0f, -2.0f)) * glm::rotate(mat4(1.0f), 0.7f, vec3(0.0f, 1.0f, 0.0f)) *
          glm::scale(mat4(1.0f), vec3(1.0f, 0.5f, 3.0f)),
      glm::translate(mat4(1.0f), vec3(2.0f, 1.2f, -1.0f)) * glm::rotate(mat4(1.0f), -1.1f, vec3(1.0f, 0.3f, 0.0f)) *
          glm::scale(mat4(1.0f), vec3(0.6f, 1.4f, 1.0f)),
      glm::translate(mat4(1.0f), vec3(4.5f, 0.8f, -7.0f)) * glm::rotate(mat4(1.0f), 0.3f, vec3(0.0f, 0.0f, 1.0f))};
  scene.instances.back().transform = transforms[0];
  for (int i = 1; i < 3; ++i) {
    Instance instance;
    instance.name = "quad copy " + std::to_string(i);
    instance.mesh = quad;
    instance.transform = transforms[i];
    scene.instances.push_back(instance);
  }
  return scene;
}

TEST_F(VisibilityGBuffer, EqualsTheRasterGBufferOnInstancedTexturedQuads) {
  const Scene scene = instanced_test_scene();
  const FrameState frame = testing::look_at(vec3(0.0f, 1.5f, 6.0f), vec3(0.0f, 0.6f, -4.0f), scene.light.position);
  const GBufferImages raster = render_gbuffer(scene, frame, 160, 96, GBufferMethod::raster);
  const GBufferImages visibility = render_gbuffer(scene, frame, 160, 96, GBufferMethod::visibility);
  const Mismatches m = compare(scene, raster, visibility);
  expect_equal_gbuffers(m, 160 * 96 / 2, software_sampler(context()));
  EXPECT_GT(m.textured, 160 * 96 / 3);
  // All three instances of the shared mesh are on screen.
  std::vector<int> pixels_of_instance(scene.instances.size(), 0);
  for (const glm::uvec2 id : visibility.ids)
    if (id.x > 0u) ++pixels_of_instance[id.x - 1u];
  for (std::size_t i = 2; i < scene.instances.size(); ++i) EXPECT_GT(pixels_of_instance[i], 20) << "instance " << i;
}

TEST_F(VisibilityGBuffer, EqualsTheRasterGBufferOnTheMirrorFloorScene) {
  const Scene scene = testing::mirror_floor_with_wall(-4.0f);
  const FrameState frame = testing::camera_looking_down_the_floor();
  const Mismatches m = compare(scene, render_gbuffer(scene, frame, 96, 64, GBufferMethod::raster),
                               render_gbuffer(scene, frame, 96, 64, GBufferMethod::visibility));
  expect_equal_gbuffers(m, 96 * 64 / 3, software_sampler(context()));
}

TEST_F(VisibilityGBuffer, EqualsTheRasterGBufferOnAnAtriumFrame) {
  const Scene scene = make_preset("atrium-simple");
  const WalkthroughAnimation animation(scene);
  for (const int frame : {2100, 4400}) {
    SCOPED_TRACE(::testing::Message() << "atrium-simple frame " << frame);
    const Mismatches m = compare(scene, render_gbuffer(scene, animation.at(frame), 128, 72, GBufferMethod::raster),
                                 render_gbuffer(scene, animation.at(frame), 128, 72, GBufferMethod::visibility));
    expect_equal_gbuffers(m, 128 * 72 / 2, software_sampler(context()));
    EXPECT_GT(m.textured, 128 * 72 / 4);
  }
}

// A textured quad facing the camera, magnified (each 4x4-texel block of the texture covers about 17x17
// pixels): wherever the raster albedo is the same in a pixel and its 8 neighbours (inside a block,
// away from any filter's reach across block edges), the visibility albedo must be that colour too.
// Swapped barycentrics or a mirrored uv put other blocks there.
TEST_F(VisibilityGBuffer, TexturedQuadFacingTheCameraMatchesInsideTexelBlocks) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 5.0f, 0.0f));
  scene.textures.push_back(block_texture());
  const std::uint32_t textured = testing::add_material(scene, vec3(1.0f), 0.0f, 0);
  // Not a parallelogram of equal triangles: corner 2 pulled in, so the two triangles' uv mappings
  // differ and a triangle id or a barycentric mix-up shows.
  const std::uint32_t quad = testing::add_quad(scene, vec3(-2.0f, -2.0f, -5.0f), vec3(4.0f, 0.0f, 0.0f),
                                               vec3(0.0f, 4.0f, 0.0f), textured);
  scene.meshes[quad].positions[2] = vec3(1.5f, 1.0f, -5.0f);
  const FrameState frame = testing::look_at(vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), scene.light.position);
  constexpr int kSize = 384;
  const GBufferImages raster = render_gbuffer(scene, frame, kSize, kSize, GBufferMethod::raster);
  const GBufferImages visibility = render_gbuffer(scene, frame, kSize, kSize, GBufferMethod::visibility);
  int compared = 0, different = 0;
  for (int y = 1; y + 1 < kSize; ++y)
    for (int x = 1; x + 1 < kSize; ++x) {
      const vec4 a = raster.albedo.at(x, y);
      if (raster.material.at(x, y).x == 0.0f) continue;
      bool uniform = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) uniform = uniform && raster.albedo.at(x + dx, y + dy) == a;
      if (!uniform) continue;
      ++compared;
      const vec3 difference = glm::abs(vec3(a) - vec3(visibility.albedo.at(x, y)));
      different += std::max({difference.x, difference.y, difference.z}) > 1.5f / 255.0f;
    }
  EXPECT_GT(compared, kSize * kSize / 10);
  EXPECT_EQ(different, 0) << "of " << compared;
}

// A whole frame (raster, shadow, lighting, SSR, rays for SSR's failures, resolve) with each method.
// The G-buffers differ only in textured albedo (see expect_equal_gbuffers) and in normals by
// half-float rounding, so the final images are nearly equal: PSNR >= 30 dB on llvmpipe (measured
// 35.1 dB, 2026-11-25: its two texture filters on textured surfaces, see expect_equal_gbuffers) and
// >= 35 dB on a GPU, where the G-buffers agree to a rounding step (H100, 2026-11-25: 59.3 dB). Swapped
// barycentrics (positions, normals and uvs rebuilt at the wrong points) gave 22.9 dB on llvmpipe,
// and fail every other test here.
TEST_F(VisibilityGBuffer, FrameRenderedWithEitherMethodIsNearlyTheSame) {
  Scene scene = make_preset("atrium-simple");
  const WalkthroughAnimation animation(scene);
  const auto render_final = [&](GBufferMethod method) {
    render::FramePipelineSettings settings;
    settings.raster.gbuffer = method;
    render::FramePipeline pipeline(scene, 128, 72, settings);
    pipeline.render(animation.at(2100));
    return pipeline.read_final();
  };
  const ImageRgba8 raster = render_final(GBufferMethod::raster);
  const ImageRgba8 visibility = render_final(GBufferMethod::visibility);
  const metrics::RmsePsnr difference = metrics::rmse_psnr(visibility, raster);
  std::printf("[ visibility ] final frame: PSNR %.2f dB against the raster G-buffer's\n", difference.psnr);
  EXPECT_GE(difference.psnr, software_sampler(context()) ? 30.0 : 35.0);
}

// The pass picks one of two programs by driver (textureGrad on GPUs, a filter in the shader on
// llvmpipe); both must compile wherever the tests run, so a CPU machine catches a broken GPU one.
TEST_F(VisibilityGBuffer, BothResolveProgramsCompile) {
  EXPECT_NE(ShaderProgram::from_embedded({"visibility_gbuffer.comp.glsl"}).id(), 0u);
  EXPECT_NE(ShaderProgram::from_embedded({"visibility_gbuffer_texel_fetch.comp.glsl"}).id(), 0u);
}

TEST(VisibilityGBufferSettings, MethodNamesRoundTripAndUnknownOnesAreErrors) {
  EXPECT_EQ(render::parse_gbuffer_method("visibility"), GBufferMethod::visibility);
  EXPECT_EQ(render::gbuffer_method_name(GBufferMethod::raster), "raster");
  EXPECT_THROW(render::parse_gbuffer_method("deferred"), Error);
}

}  // namespace
}  // namespace glint
