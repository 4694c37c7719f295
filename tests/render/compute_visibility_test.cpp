// The compute rasteriser (--primary compute, ComputeVisibilityPass) against the id draw
// (VisibilityIdPass): the same ids on every pixel but those where the two may rightly disagree, the
// same depths, and the same G-buffer wherever the ids agree. A pixel may differ only where
//   - its centre lies within kEdgeTolerancePixels of an edge of one of the two triangles (the
//     corners' float transforms can differ by an ulp, which moves a snapped corner by 1/256 pixel),
//   - or both triangles cover the centre at depths that nearly tie (kDepthTieTolerance, plus what
//     a 1/256-pixel shift changes on a steep depth plane): which one wins is float rounding.
// Each differing pixel is checked against those two explanations with the scene's own geometry on
// the CPU (in double), not just counted.
#include "metrics/rmse_psnr.h"
#include "raster_test_scene.h"
#include "transformed_scene.h"
#include "render/compute_visibility_pass.h"
#include "render/frame_constants.h"
#include "render/frame_pipeline.h"
#include "render/raster_pipeline.h"
#include "render/render_targets.h"
#include "render/texture_readback.h"
#include "render/visibility_id_pass.h"
#include "scene/camera_path.h"
#include "scene/presets.h"
#include "../gl/gl_test_context.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace glint::render {
namespace {

using ComputeVisibility = testing::GlTest;
using dvec2 = glm::dvec2;
using dvec4 = glm::dvec4;

constexpr double kEdgeTolerancePixels = 1.0 / 64.0;
constexpr double kDepthTieTolerance = 1e-6;  // window depth; about 16 float steps near 1

struct Frame {
  std::vector<glm::uvec2> ids;  // top row first
  ImageRgbaF depth, albedo, position, normal, material;
  FrameConstants constants;
  std::optional<ComputeVisibilityStats> stats;
};

RasterSettings visibility_settings(PrimaryVisibility primary) {
  RasterSettings settings;
  settings.gbuffer = GBufferMethod::visibility;
  settings.primary = primary;
  return settings;
}

Frame read_frame(const RasterPipeline& raster) {
  Frame f{read_visibility_ids(raster.visibility_id(), raster.width(), raster.height()),
          raster.read_rgbaf(RasterOutput::Depth),
          raster.read_rgbaf(RasterOutput::AlbedoReflectivity),
          raster.read_rgbaf(RasterOutput::WorldPosition),
          raster.read_rgbaf(RasterOutput::WorldNormalRoughness),
          raster.read_rgbaf(RasterOutput::MaterialId),
          raster.frame_constants(),
          std::nullopt};
  if (raster.compute_visibility() != nullptr) f.stats = raster.compute_visibility()->read_stats();
  return f;
}

Frame render_frame(const Scene& scene, const FrameState& state, int width, int height, PrimaryVisibility primary) {
  RasterPipeline raster(scene, width, height, visibility_settings(primary));
  raster.render(state);
  EXPECT_EQ(raster.compute_visibility() != nullptr, primary == PrimaryVisibility::compute);
  return read_frame(raster);
}

// A triangle as the camera sees it: its window-space polygon (x, y in pixels with y up, z the window
// depth) after clipping by the near plane, as GL clips.
struct WindowPolygon {
  std::vector<glm::dvec3> corners;
};

WindowPolygon window_polygon(const Scene& scene, const FrameConstants& constants, glm::uvec2 id) {
  WindowPolygon polygon;
  if (id.x == 0u || id.x > scene.instances.size()) return polygon;
  const Instance& instance = scene.instances[id.x - 1u];
  const Mesh& mesh = scene.meshes[instance.mesh];
  if (3u * id.y + 2u >= mesh.indices.size()) return polygon;
  const glm::dmat4 to_clip = glm::dmat4(constants.view_projection) * glm::dmat4(instance.transform);
  std::vector<dvec4> clip;
  for (unsigned i = 0; i < 3; ++i) clip.push_back(to_clip * dvec4(glm::dvec3(mesh.positions[mesh.indices[3u * id.y + i]]), 1.0));
  std::vector<dvec4> kept;  // Sutherland-Hodgman against z >= -w
  for (std::size_t i = 0; i < clip.size(); ++i) {
    const dvec4 p = clip[i], q = clip[(i + 1) % clip.size()];
    const double dp = p.z + p.w, dq = q.z + q.w;
    if (dp >= 0.0) kept.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) kept.push_back(p + (q - p) * (dp / (dp - dq)));
  }
  const dvec2 size(constants.viewport.x, constants.viewport.y);
  for (const dvec4& p : kept)
    polygon.corners.push_back(glm::dvec3((dvec2(p) / p.w * 0.5 + 0.5) * size, p.z / p.w * 0.5 + 0.5));
  return polygon;
}

double distance_to_segment(dvec2 p, dvec2 a, dvec2 b) {
  const double t = glm::clamp(glm::dot(p - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-300), 0.0, 1.0);
  return glm::length(p - (a + t * (b - a)));
}

struct CentreRelation {
  double edge_distance = 1e300;  // pixels to the nearest edge of the polygon
  bool inside = false;
  double depth = 0.0;            // at the centre, on the polygon's plane
  double depth_per_pixel = 0.0;  // |dz/dx| + |dz/dy|
};

CentreRelation relate(const WindowPolygon& polygon, dvec2 centre) {
  CentreRelation r;
  const std::size_t n = polygon.corners.size();
  if (n < 3) return r;
  const auto cross = [](dvec2 u, dvec2 v) { return u.x * v.y - u.y * v.x; };
  int positive = 0, negative = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const dvec2 a(polygon.corners[i]), b(polygon.corners[(i + 1) % n]);
    r.edge_distance = std::min(r.edge_distance, distance_to_segment(centre, a, b));
    const double side = cross(b - a, centre - a);
    positive += side > 0.0;
    negative += side < 0.0;
  }
  r.inside = positive == 0 || negative == 0;
  // The depth plane through the first three corners: z = z0 + g . (p - p0).
  const glm::dvec3 c0 = polygon.corners[0], c1 = polygon.corners[1], c2 = polygon.corners[2];
  const dvec2 e1 = dvec2(c1) - dvec2(c0), e2 = dvec2(c2) - dvec2(c0);
  const double det = cross(e1, e2);
  if (det != 0.0) {
    const dvec2 gradient((c1.z - c0.z) * e2.y - (c2.z - c0.z) * e1.y, (c2.z - c0.z) * e1.x - (c1.z - c0.z) * e2.x);
    const dvec2 g = gradient / det;
    r.depth = c0.z + glm::dot(g, centre - dvec2(c0));
    r.depth_per_pixel = std::abs(g.x) + std::abs(g.y);
  }
  return r;
}

struct IdComparison {
  int geometry = 0;           // pixels the id draw covers
  int different = 0;          // ids differ
  int on_edge = 0;            // ... explained by an edge
  int depth_tie = 0;          // ... explained by a depth tie
  int unexplained = 0;
  int gbuffer = 0;            // equal ids, but a G-buffer texel differs
  int depth = 0;              // equal ids, depth beyond tolerance
  double worst_depth = 0.0;   // over equal-id geometry pixels, relative to the tolerance there
};

double depth_tolerance(double depth_per_pixel) { return kDepthTieTolerance + depth_per_pixel / 256.0; }

IdComparison compare(const Scene& scene, const Frame& raster, const Frame& computed) {
  IdComparison c;
  const int width = raster.depth.width, height = raster.depth.height;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x);
      const glm::uvec2 a = raster.ids[i], b = computed.ids[i];
      c.geometry += a.x != 0u;
      const dvec2 centre(x + 0.5, height - y - 0.5);  // window space, y up
      if (a == b) {
        c.gbuffer += raster.albedo.at(x, y) != computed.albedo.at(x, y) ||
                     raster.position.at(x, y) != computed.position.at(x, y) ||
                     raster.normal.at(x, y) != computed.normal.at(x, y) ||
                     raster.material.at(x, y) != computed.material.at(x, y);
        const double d = std::abs(static_cast<double>(raster.depth.at(x, y).x) - computed.depth.at(x, y).x);
        if (a.x == 0u) {
          c.depth += d != 0.0;
        } else {
          const double tolerance = depth_tolerance(relate(window_polygon(scene, raster.constants, a), centre).depth_per_pixel);
          c.depth += d > tolerance;
          c.worst_depth = std::max(c.worst_depth, d / tolerance);
        }
        continue;
      }
      ++c.different;
      const CentreRelation ra = relate(window_polygon(scene, raster.constants, a), centre);
      const CentreRelation rb = relate(window_polygon(scene, raster.constants, b), centre);
      if (std::min(ra.edge_distance, rb.edge_distance) <= kEdgeTolerancePixels) {
        ++c.on_edge;
      } else if (a.x != 0u && b.x != 0u && ra.inside && rb.inside &&
                 std::abs(ra.depth - rb.depth) <= depth_tolerance(std::max(ra.depth_per_pixel, rb.depth_per_pixel))) {
        ++c.depth_tie;
      } else {
        ++c.unexplained;
        if (c.unexplained <= 5)
          std::printf("[ compute ] unexplained pixel (%d, %d): raster {%u, %u} compute {%u, %u}, edges %.4g / %.4g px, "
                      "depths %.9g / %.9g\n",
                      x, y, a.x, a.y, b.x, b.y, ra.edge_distance, rb.edge_distance, ra.depth, rb.depth);
      }
    }
  std::printf("[ compute ] %d geometry pixels, %d ids differ (%d on an edge, %d depth ties, %d unexplained), %d G-buffer "
              "and %d depth differences, worst depth %.3g of its tolerance\n",
              c.geometry, c.different, c.on_edge, c.depth_tie, c.unexplained, c.gbuffer, c.depth, c.worst_depth);
  return c;
}

// Every difference explained, few of them (edges and ties only: at most 1 in 50 covered pixels), the
// same G-buffer and depths where the ids agree.
void expect_same_visibility(const IdComparison& c, int min_geometry) {
  EXPECT_GE(c.geometry, min_geometry);
  EXPECT_EQ(c.unexplained, 0);
  EXPECT_LE(c.different, c.geometry / 50 + 2);
  EXPECT_EQ(c.gbuffer, 0);
  EXPECT_EQ(c.depth, 0);
}

// A textured-free variant of the G-buffer test's instanced scene: a floor reaching behind the
// camera (its triangles cross the near plane), a wall, and one quad mesh drawn by three instances
// under rotations and non-uniform scales, one partly behind the wall.
Scene instanced_scene() {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 6.0f, 0.0f));
  const std::uint32_t floor_material = testing::add_material(scene, vec3(0.8f), 0.4f);
  const std::uint32_t wall_material = testing::add_material(scene, vec3(0.3f, 0.6f, 0.2f), 0.1f);
  const std::uint32_t box_material = testing::add_material(scene, vec3(0.9f, 0.8f, 1.0f));
  testing::add_quad(scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), floor_material);
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

FrameState instanced_scene_camera(const Scene& scene) {
  return testing::look_at(vec3(0.0f, 1.5f, 6.0f), vec3(0.0f, 0.6f, -4.0f), scene.light.position);
}

// Whether some triangle of instance `instance` has a corner behind the camera (clip w <= 0).
bool crosses_behind_camera(const Scene& scene, const FrameConstants& constants, std::uint32_t instance) {
  const Instance& in = scene.instances[instance];
  for (const vec3& p : scene.meshes[in.mesh].positions)
    if ((constants.view_projection * in.transform * vec4(p, 1.0f)).w <= 0.0f) return true;
  return false;
}

TEST_F(ComputeVisibility, IdsEqualTheIdDrawOnInstancedQuads) {
  const Scene scene = instanced_scene();
  const FrameState state = instanced_scene_camera(scene);
  const Frame raster = render_frame(scene, state, 160, 96, PrimaryVisibility::raster);
  const Frame computed = render_frame(scene, state, 160, 96, PrimaryVisibility::compute);
  expect_same_visibility(compare(scene, raster, computed), 160 * 96 / 2);
  EXPECT_TRUE(crosses_behind_camera(scene, raster.constants, 0));  // the floor: near-plane clipping
  std::vector<int> pixels_of_instance(scene.instances.size(), 0);
  for (const glm::uvec2 id : computed.ids)
    if (id.x > 0u) ++pixels_of_instance[id.x - 1u];
  for (std::size_t i = 0; i < scene.instances.size(); ++i) EXPECT_GT(pixels_of_instance[i], 20) << "instance " << i;
}

TEST_F(ComputeVisibility, IdsEqualTheIdDrawOnTheMirrorFloorScene) {
  const Scene scene = testing::mirror_floor_with_wall(-4.0f);
  const FrameState state = testing::camera_looking_down_the_floor();
  const Frame raster = render_frame(scene, state, 96, 64, PrimaryVisibility::raster);
  expect_same_visibility(compare(scene, raster, render_frame(scene, state, 96, 64, PrimaryVisibility::compute)),
                         96 * 64 / 3);
}

TEST_F(ComputeVisibility, IdsEqualTheIdDrawOnAtriumFrames) {
  std::uint32_t large_entries = 0;
  for (const char* preset : {"atrium-simple", "atrium"}) {
    const Scene scene = make_preset(preset);
    const WalkthroughAnimation animation(scene);
    for (const int frame : {2100, 4400}) {
      SCOPED_TRACE(::testing::Message() << preset << " frame " << frame);
      const Frame raster = render_frame(scene, animation.at(frame), 160, 90, PrimaryVisibility::raster);
      const Frame computed = render_frame(scene, animation.at(frame), 160, 90, PrimaryVisibility::compute);
      expect_same_visibility(compare(scene, raster, computed), 160 * 90 / 2);
      ASSERT_TRUE(computed.stats);
      EXPECT_EQ(computed.stats->overflowed, 0u);
      large_entries += computed.stats->large_entries;
    }
  }
  EXPECT_GT(large_entries, 0u);  // the tile dispatch drew some of it
}

// One triangle mesh (normals facing +z) as its own instance; returns the mesh index.
std::uint32_t add_triangle(Scene& scene, vec3 a, vec3 b, vec3 c, std::uint32_t material) {
  Mesh mesh;
  mesh.name = "triangle" + std::to_string(scene.meshes.size());
  mesh.positions = {a, b, c};
  mesh.normals.assign(3, glm::normalize(glm::cross(b - a, c - a)));
  mesh.uvs.assign(3, vec2(0.0f));
  mesh.indices = {0, 1, 2};
  mesh.material = material;
  scene.meshes.push_back(mesh);
  Instance instance;
  instance.name = mesh.name;
  instance.mesh = static_cast<std::uint32_t>(scene.meshes.size() - 1);
  scene.instances.push_back(instance);
  return instance.mesh;
}

// A triangle 400 times wider than the view in front of the camera (far beyond the guard band:
// clipped, fanned, drawn by the tile dispatch), another behind it that must never show: every
// pixel is the front one's, at the id draw's depth.
TEST_F(ComputeVisibility, TriangleLargerThanTheScreenCoversEveryPixel) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 3.0f, 0.0f));
  const std::uint32_t material = testing::add_material(scene, vec3(0.5f));
  add_triangle(scene, vec3(-1000.0f, -1000.0f, -5.0f), vec3(1000.0f, -1000.0f, -5.0f), vec3(0.0f, 1000.0f, -5.0f), material);
  add_triangle(scene, vec3(-900.0f, -900.0f, -6.0f), vec3(900.0f, -900.0f, -6.0f), vec3(0.0f, 900.0f, -6.0f), material);
  const FrameState state = testing::look_at(vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), scene.light.position);
  const Frame raster = render_frame(scene, state, 80, 48, PrimaryVisibility::raster);
  const Frame computed = render_frame(scene, state, 80, 48, PrimaryVisibility::compute);
  int front = 0;
  for (const glm::uvec2 id : computed.ids) front += id == glm::uvec2(1u, 0u);
  EXPECT_EQ(front, 80 * 48);
  expect_same_visibility(compare(scene, raster, computed), 80 * 48);
  ASSERT_TRUE(computed.stats);
  EXPECT_EQ(computed.stats->deferred, 2u);
  // Each covers all 10 x 6 tiles of 8 x 8 pixels, and a record holds at most 8 of a triangle's tiles.
  EXPECT_GE(computed.stats->chunks, 2u * 8u);
}

// A ramp through the near plane inside the view: its near corners are behind the camera, and GL
// clips it along the near plane across the middle of the screen (upper half drawn, at depths from
// 0). The floor behind it crosses the near plane too (instanced_scene's camera test checks that).
TEST_F(ComputeVisibility, TriangleCrossingTheNearPlaneIsClippedThere) {
  Scene scene = testing::make_empty_test_scene(vec3(0.0f, 3.0f, 0.0f));
  const std::uint32_t ramp = testing::add_material(scene, vec3(0.9f, 0.3f, 0.3f));
  const std::uint32_t back = testing::add_material(scene, vec3(0.3f, 0.3f, 0.9f));
  // y = 0.5 (-z - near), with near the clip range's for the scene's bounds (those of the back quad
  // and the ramp's near end): y = 0 on the near plane.
  const float near = clip_range_for(Aabb{vec3(-4.0f, -3.0f, -4.0f), vec3(4.0f, 3.0f, 0.05f)}).x;
  testing::add_quad(scene, vec3(-1.0f, -0.025f - 0.5f * near, 0.05f), vec3(2.0f, 0.0f, 0.0f),
                    vec3(0.0f, 1.025f, -2.05f), ramp);
  testing::add_quad(scene, vec3(-4.0f, -3.0f, -4.0f), vec3(8.0f, 0.0f, 0.0f), vec3(0.0f, 6.0f, 0.0f), back);
  const FrameState state = testing::look_at(vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), scene.light.position);
  const Frame raster = render_frame(scene, state, 96, 64, PrimaryVisibility::raster);
  const Frame computed = render_frame(scene, state, 96, 64, PrimaryVisibility::compute);
  ASSERT_EQ(raster.constants.near_far.x, near);
  EXPECT_TRUE(crosses_behind_camera(scene, raster.constants, 0));
  expect_same_visibility(compare(scene, raster, computed), 96 * 64 / 2);
  // The ramp holds most of the upper half and nothing of the lower one.
  int upper = 0, lower = 0;
  for (int y = 0; y < 64; ++y)
    for (int x = 0; x < 96; ++x) (y < 32 ? upper : lower) += computed.ids[static_cast<std::size_t>(y * 96 + x)].x == 1u;
  EXPECT_GT(upper, 96 * 32 * 3 / 4);
  EXPECT_EQ(lower, 0);
}

// The instanced scene scaled by 1000 and moved 1e4 away from the origin (camera and light with it):
// no threshold depends on the scene's size or place, so the same pixels agree.
TEST_F(ComputeVisibility, ScaledAndTranslatedSceneGivesTheSameIds) {
  Scene scene = instanced_scene();
  const mat4 move = glm::translate(mat4(1.0f), vec3(1e4f, -1e4f, 1e4f)) * glm::scale(mat4(1.0f), vec3(1000.0f));
  for (Instance& instance : scene.instances) instance.transform = move * instance.transform;
  scene.light.position = vec3(move * vec4(scene.light.position, 1.0f));
  scene.light.range *= 1000.0f;
  FrameState state = instanced_scene_camera(instanced_scene());
  state.camera.position = vec3(move * vec4(state.camera.position, 1.0f));
  state.camera.target = vec3(move * vec4(state.camera.target, 1.0f));
  state.light_position = scene.light.position;
  const Frame raster = render_frame(scene, state, 160, 96, PrimaryVisibility::raster);
  const Frame computed = render_frame(scene, state, 160, 96, PrimaryVisibility::compute);
  expect_same_visibility(compare(scene, raster, computed), 160 * 96 / 2);
  // The same picture as the unscaled scene's, up to edge pixels.
  const Frame unscaled = render_frame(instanced_scene(), instanced_scene_camera(instanced_scene()), 160, 96,
                                      PrimaryVisibility::compute);
  int different = 0;
  for (std::size_t i = 0; i < unscaled.ids.size(); ++i) different += unscaled.ids[i] != computed.ids[i];
  EXPECT_LE(different, 160 * 96 / 100);
}

// A quad facing the camera tessellated into a grid whose corners sit exactly on pixel centres, so
// that edges (grid lines and diagonals) run through centres: the fill rule decides every one of
// them. Cell sides of 1 and 2 pixels (small triangles, one invocation each) and 20 pixels (large:
// the tile dispatch). No background pixel may show (a crack: a strict rule on every edge left all
// 3072 pixels empty with 1- and 2-pixel cells, 513 with 20-pixel ones), and on llvmpipe, whose
// rasteriser uses the same rule, the ids must equal the id draw's exactly (measured on llvmpipe: a
// top-left rule gave 1536 and 192 different ids with 2- and 20-pixel cells; an inclusive rule, which
// gives centres on edges to both triangles and so to the first in draw order, 3072, 2688 and 439).
// Other drivers may own such centres the other way: edge pixels only.
TEST_F(ComputeVisibility, TessellatedQuadOnPixelCentresHasNoCracks) {
  constexpr int kWidth = 64, kHeight = 48;
  const bool software = context().renderer().find("llvmpipe") != std::string::npos;
  for (const int cell : {1, 2, 20}) {
    SCOPED_TRACE(::testing::Message() << "cells of " << cell << " pixels");
    Scene scene = testing::make_empty_test_scene(vec3(0.0f, 3.0f, 0.0f));
    const std::uint32_t material = testing::add_material(scene, vec3(0.5f));
    // World point on the plane z = -1 whose projection is window position (px, py), y up.
    const float tan_half = std::tan(glm::radians(30.0f)), aspect = static_cast<float>(kWidth) / kHeight;
    const auto at = [&](float px, float py) {
      return vec3((px / kWidth * 2.0f - 1.0f) * tan_half * aspect, (py / kHeight * 2.0f - 1.0f) * tan_half, -1.0f);
    };
    Mesh grid;
    grid.name = "grid";
    const int columns = kWidth / cell + 3, rows = kHeight / cell + 3;  // one cell beyond every side
    for (int j = 0; j <= rows; ++j)
      for (int i = 0; i <= columns; ++i) {
        grid.positions.push_back(at(static_cast<float>((i - 1) * cell) + 0.5f, static_cast<float>((j - 1) * cell) + 0.5f));
        grid.normals.push_back(vec3(0.0f, 0.0f, 1.0f));
        grid.uvs.push_back(vec2(0.0f));
      }
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < columns; ++i) {
        const auto v = [&](int di, int dj) { return static_cast<std::uint32_t>((j + dj) * (columns + 1) + i + di); };
        if ((i + j) % 2 == 0)  // alternate the diagonal, and the winding of every other triangle
          grid.indices.insert(grid.indices.end(), {v(0, 0), v(1, 0), v(1, 1), v(0, 0), v(0, 1), v(1, 1)});
        else
          grid.indices.insert(grid.indices.end(), {v(0, 0), v(1, 0), v(0, 1), v(1, 0), v(1, 1), v(0, 1)});
      }
    grid.material = material;
    scene.meshes.push_back(grid);
    Instance instance;
    instance.name = "grid";
    instance.mesh = 0;
    scene.instances.push_back(instance);
    const FrameState state = testing::look_at(vec3(0.0f), vec3(0.0f, 0.0f, -1.0f), scene.light.position);
    const Frame raster = render_frame(scene, state, kWidth, kHeight, PrimaryVisibility::raster);
    const Frame computed = render_frame(scene, state, kWidth, kHeight, PrimaryVisibility::compute);
    int background = 0;
    for (const glm::uvec2 id : computed.ids) background += id.x == 0u;
    EXPECT_EQ(background, 0);
    const IdComparison c = compare(scene, raster, computed);
    EXPECT_EQ(c.geometry, kWidth * kHeight);
    EXPECT_EQ(c.unexplained, 0);
    EXPECT_EQ(c.gbuffer, 0);
    EXPECT_EQ(c.depth, 0);
    if (software) {
      EXPECT_EQ(c.different, 0);
    }
    ASSERT_TRUE(computed.stats);
    if (cell == 20) {
      EXPECT_GT(computed.stats->large_entries, 0u);
    }
  }
}

// Two instances of one quad at the same place tie at every pixel with the very same depth bits: the
// id draw's GL_LESS keeps the first drawn, and so must round 1 (the smallest draw-order number among
// the triangles at the kept depth). The wall is drawn twice too. With the last writer kept instead,
// the copies took all 1045 of those pixels (llvmpipe).
TEST_F(ComputeVisibility, ExactDepthTiesGoToTheFirstInDrawOrder) {
  Scene scene = instanced_scene();
  for (const std::uint32_t original : {1u, 2u}) {
    Instance copy = scene.instances[original];
    copy.name += " again";
    scene.instances.push_back(copy);
  }
  const FrameState state = instanced_scene_camera(scene);
  const Frame raster = render_frame(scene, state, 160, 96, PrimaryVisibility::raster);
  const Frame computed = render_frame(scene, state, 160, 96, PrimaryVisibility::compute);
  const IdComparison c = compare(scene, raster, computed);
  expect_same_visibility(c, 160 * 96 / 2);
  int copies = 0, originals = 0;
  for (const glm::uvec2 id : computed.ids) {
    copies += id.x > 5u;
    originals += id.x == 2u || id.x == 3u;
  }
  EXPECT_EQ(copies, 0);
  EXPECT_GT(originals, 160 * 96 / 20);
}

// The pass alone with a given large-triangle capacity: ids and depth.
struct PassOutput {
  std::vector<glm::uvec2> ids;
  ImageRgbaF depth;
  ComputeVisibilityStats stats;
};

PassOutput run_pass(const Scene& scene, const FrameState& state, int width, int height,
                    const ComputeVisibilityOptions& options) {
  const GpuScene gpu_scene(scene);
  const RasterTargets targets(width, height, true);
  ComputeVisibilityPass pass(targets, gpu_scene, options);
  const FrameConstants constants = make_frame_constants(scene, scene.world_bounds(), state, width, height);
  const GlBuffer buffer = create_buffer(sizeof(FrameConstants), &constants);
  glBindBufferBase(GL_UNIFORM_BUFFER, kFrameConstantsBinding, buffer.id());
  pass.run();
  pass.write_depth();  // the depth target is written on demand
  return {read_visibility_ids(targets.visibility_id.id(), width, height),
          read_texture_rgbaf(targets.depth.id(), kDepthFormat, width, height), pass.read_stats()};
}

// With a large-triangle list or a chunk list too small, the triangles that find it full are drawn
// by their own invocation in both rounds: the same ids and depths, bit for bit.
TEST_F(ComputeVisibility, FullLargeTriangleListGivesTheSameImages) {
  const Scene scene = make_preset("atrium-simple");
  const FrameState state = WalkthroughAnimation(scene).at(4400);
  const PassOutput listed = run_pass(scene, state, 160, 90, {});
  EXPECT_EQ(listed.stats.overflowed, 0u);
  EXPECT_GT(listed.stats.large_entries, 3u);
  EXPECT_GT(listed.stats.chunks, 3u);
  const PassOutput full_entries = run_pass(scene, state, 160, 90, {.large_triangle_capacity = 3});
  EXPECT_GT(full_entries.stats.overflowed, 0u);
  EXPECT_LE(full_entries.stats.large_entries, 3u);
  const PassOutput full_chunks = run_pass(scene, state, 160, 90, {.tile_chunk_capacity = 3});
  EXPECT_GT(full_chunks.stats.overflowed, 0u);
  EXPECT_LE(full_chunks.stats.chunks, 3u);
  for (const PassOutput* full : {&full_entries, &full_chunks}) {
    EXPECT_TRUE(listed.ids == full->ids);
    EXPECT_TRUE(listed.depth.pixels == full->depth.pixels);
  }
}

// Where the driver has 64-bit atomics (NVIDIA), one round of {depth, triangle} minima must keep what
// the two 32-bit rounds keep, bit for bit: on an atrium frame (large and clipped triangles, a full
// large-triangle list too) and on exact depth ties, where the first triangle in draw order wins.
TEST_F(ComputeVisibility, OneRoundOf64BitAtomicsEqualsTwoRounds) {
  const Scene atrium = make_preset("atrium-simple");
  Scene ties = instanced_scene();
  ties.instances.push_back(ties.instances[1]);
  const std::vector<std::pair<const Scene*, FrameState>> cases = {
      {&atrium, WalkthroughAnimation(atrium).at(4400)}, {&atrium, WalkthroughAnimation(atrium).at(2100)},
      {&ties, instanced_scene_camera(ties)}};
  {
    const GpuScene gpu_scene(atrium);
    const RasterTargets targets(16, 16, true);
    if (!ComputeVisibilityPass(targets, gpu_scene).one_round())
      GTEST_SKIP() << "this GL has no 64-bit atomics on storage buffers (GL_NV_shader_atomic_int64)";
  }
  for (const auto& [scene, state] : cases) {
    for (const std::uint32_t capacity : {0u, 3u}) {
      const PassOutput one =
          run_pass(*scene, state, 203, 117, {.large_triangle_capacity = capacity, .tile_chunk_capacity = capacity});
      const PassOutput two = run_pass(
          *scene, state, 203, 117,
          {.large_triangle_capacity = capacity, .tile_chunk_capacity = capacity, .use_64_bit_atomics = false});
      EXPECT_TRUE(one.ids == two.ids) << "capacity " << capacity;
      EXPECT_TRUE(one.depth.pixels == two.depth.pixels) << "capacity " << capacity;
      EXPECT_EQ(one.stats.large_entries, two.stats.large_entries);
      // With full lists, which triangles fall back (and so how many) depends on the order in which
      // their work groups reserve entries and chunk records; whether any does, and the images, do not.
      EXPECT_EQ(one.stats.overflowed > 0, two.stats.overflowed > 0) << "capacity " << capacity;
      if (capacity == 0) {
        EXPECT_EQ(one.stats.overflowed, 0u);
      }
    }
  }
}

// Vertices are read every frame: after a mesh moves in the GpuScene (as deforming meshes do), the
// ids follow it as the id draw's do.
TEST_F(ComputeVisibility, MovedVerticesAreSeenNextFrame) {
  const Scene scene = instanced_scene();
  const FrameState state = instanced_scene_camera(scene);
  const Mesh& wall = scene.meshes[1];
  std::vector<vec3> moved = wall.positions;
  for (vec3& p : moved) p += vec3(2.5f, 0.5f, 1.0f);
  std::vector<Frame> frames;
  for (const PrimaryVisibility primary : {PrimaryVisibility::raster, PrimaryVisibility::compute}) {
    RasterPipeline raster(scene, 120, 80, visibility_settings(primary));
    raster.render(state);
    frames.push_back(read_frame(raster));
    raster.gpu_scene().update_mesh_vertices(1, moved, wall.normals);
    raster.render(state);
    frames.push_back(read_frame(raster));
  }
  int changed = 0;
  for (std::size_t i = 0; i < frames[2].ids.size(); ++i) changed += frames[2].ids[i] != frames[3].ids[i];
  EXPECT_GT(changed, 120 * 80 / 20);
  Scene moved_scene = scene;
  moved_scene.meshes[1].positions = moved;
  expect_same_visibility(compare(moved_scene, frames[1], frames[3]), 120 * 80 / 2);
}

// A whole frame (SSR, hybrid reflections, cube shadows, resolve) with the compute rasteriser's ids:
// the ids differ from the id draw's on a few edge pixels only, the rest of the frame reads the same
// G-buffer. An edge pixel that changes surface changes its colour fully, and SSR and the blur carry
// it to a few neighbours, so the bound is on how many pixels differ (at most 1 %), not on a PSNR
// fitted to one GPU (llvmpipe: 2 of 14400 pixels, PSNR 64.9 dB; an H100: PSNR 43.5 dB).
TEST_F(ComputeVisibility, FrameIsNearlyTheIdDrawsFrame) {
  const Scene scene = make_preset("atrium-simple");
  const FrameState state = WalkthroughAnimation(scene).at(2100);
  const auto render_final = [&](PrimaryVisibility primary) {
    FramePipelineSettings settings;
    settings.reflections = ReflectionMode::hybrid;
    settings.raster = visibility_settings(primary);
    settings.ray_tracing.backend = "embree";
    FramePipeline pipeline(scene, 160, 90, settings);
    pipeline.render(state);
    return pipeline.read_final();
  };
  const ImageRgba8 compute = render_final(PrimaryVisibility::compute);
  const ImageRgba8 raster = render_final(PrimaryVisibility::raster);
  const double psnr = metrics::rmse_psnr(compute, raster).psnr;
  const testing::ImageDifference difference = testing::image_difference(compute, raster);
  std::printf("[ compute ] final frame: PSNR %.2f dB against the id draw's, %s\n", psnr, difference.text().c_str());
  EXPECT_LE(difference.pixels, 160 * 90 / 100);
  EXPECT_GE(psnr, 35.0);
}

TEST(ComputeVisibilitySettings, NameRoundTripsAndNeedsTheVisibilityGBuffer) {
  EXPECT_EQ(parse_primary_visibility("compute"), PrimaryVisibility::compute);
  EXPECT_EQ(primary_visibility_name(PrimaryVisibility::compute), "compute");
  RasterSettings settings;
  settings.primary = PrimaryVisibility::compute;
  EXPECT_THROW(settings.validate(), Error);  // with the raster G-buffer
  settings.gbuffer = GBufferMethod::visibility;
  EXPECT_NO_THROW(settings.validate());
  FramePipelineSettings frame;
  frame.raster = settings;
  frame.reflections = ReflectionMode::ssr;
  frame.shadows.method = ShadowMethod::cube;
  EXPECT_FALSE(uses_ray_tracer(frame));  // no tracer for the ids
}

}  // namespace
}  // namespace glint::render
