// Camera-relative rendering (docs/render.md "Clip range, and precision far from the origin"): a
// scene moved far from the origin renders the picture it renders at the origin. Every pass that
// turns world positions into clip or view space subtracts the camera first (the shadow cube map:
// the light), so the rounding of coordinates near 1e5 (about 0.008) moves a point as a whole
// instead of entering clip z and w separately; before, a small room moved 1e5 away had its floor
// drawn over the boxes standing on it and speckles where surfaces meet.
#include "render/frame_pipeline.h"
#include "render/ray_origin_offset.h"
#include "raster_test_scene.h"
#include "transformed_scene.h"
#include "scene/presets.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <string>

namespace glint::render {
namespace {

using testing::add_material;
using testing::add_quad;
using testing::image_difference;
using testing::ImageDifference;
using testing::transformed;

constexpr int kWidth = 160;
constexpr int kHeight = 90;
// Where the copies go: far along x (coordinates near 1e5, steps of 0.0078) and along -z.
const vec3 kOffsets[] = {vec3(1.0e5f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -3.0e4f)};

// The five visible faces of the box [lo, hi] (no bottom), each its own quad facing out.
void add_box(Scene& scene, vec3 lo, vec3 hi, std::uint32_t material) {
  const vec3 d = hi - lo;
  add_quad(scene, vec3(hi.x, lo.y, hi.z), vec3(0, 0, -d.z), vec3(0, d.y, 0), material);  // +x
  add_quad(scene, vec3(lo.x, lo.y, lo.z), vec3(0, 0, d.z), vec3(0, d.y, 0), material);   // -x
  add_quad(scene, vec3(lo.x, lo.y, hi.z), vec3(d.x, 0, 0), vec3(0, d.y, 0), material);   // +z
  add_quad(scene, vec3(hi.x, lo.y, lo.z), vec3(-d.x, 0, 0), vec3(0, d.y, 0), material);  // -z
  add_quad(scene, vec3(lo.x, hi.y, hi.z), vec3(d.x, 0, 0), vec3(0, 0, -d.z), material);  // +y
}

// Every coordinate of the room, camera and light is a multiple of 1/64, so the copies moved by 1e5
// (float steps of 1/128 there) or 3e4 hold exactly the same geometry: what differs is the renderer's
// rounding alone. (Coordinates like 0.1 round by up to 0.004 when moved: the camera turns by a few
// hundredths of a pixel and whole edges of pixels flip, whatever the renderer does.)
const vec3 kLight(-0.25f, 2.625f, 1.25f);

// A small room (8 x 3 x 8): a reflective floor, two walls, two boxes standing on the floor, the
// light inside. Its near plane is 1/10000 of the far one, as every scene's (frame_constants.h).
Scene small_room() {
  Scene scene = testing::make_empty_test_scene(kLight);
  const std::uint32_t floor = add_material(scene, vec3(0.6f, 0.55f, 0.5f), 0.5f);
  const std::uint32_t wall = add_material(scene, vec3(0.8f, 0.8f, 0.7f), 0.2f);
  const std::uint32_t red = add_material(scene, vec3(0.8f, 0.15f, 0.1f));
  const std::uint32_t blue = add_material(scene, vec3(0.1f, 0.3f, 0.8f), 0.3f);
  add_quad(scene, vec3(-4, 0, 4), vec3(8, 0, 0), vec3(0, 0, -8), floor);
  add_quad(scene, vec3(-4, 0, -4), vec3(8, 0, 0), vec3(0, 3, 0), wall);  // back wall, facing +z
  add_quad(scene, vec3(-4, 0, 4), vec3(0, 0, -8), vec3(0, 3, 0), wall);  // left wall, facing +x
  add_box(scene, vec3(-1.5f, 0.0f, -1.5f), vec3(-0.5f, 1.0f, -0.5f), red);
  add_box(scene, vec3(0.625f, 0.0f, -0.25f), vec3(1.25f, 1.5f, 0.375f), blue);
  return scene;
}

FrameState room_frame() {
  return testing::look_at(vec3(0.0f, 1.375f, 4.0f), vec3(-0.125f, 0.5f, -1.0f), kLight);
}

struct Picture {
  ImageRgba8 final;
  ImageRgba8 depth;
  ImageRgba8 normals;
};

Picture render(const Scene& scene, const FrameState& frame, const FramePipelineSettings& settings) {
  FramePipeline pipeline(scene, kWidth, kHeight, settings);
  pipeline.render(frame);
  Picture picture{pipeline.read_final(), {}, {}};
  for (DebugView& view : pipeline.read_debug_views()) {
    if (view.name == "depth") picture.depth = std::move(view.image);
    if (view.name == "normals") picture.normals = std::move(view.image);
  }
  return picture;
}

// The G-buffer (depth and normal views) may differ by more than 8 levels in this many pixels of
// 14400: none with the rasterised G-buffers (the largest difference is 1 level), 4 with rt primary
// visibility, whose ray origins are world points rounded to 0.0078 at 1e5 (measured on llvmpipe).
// Before camera-relative rendering: 276 depth and 341 normal pixels moved by -3e4.
constexpr int kEdgePixels = 8;
// The final image, 1/300 of the pixels: shadow edges and contacts still move by a pixel here and
// there because the G-buffer stores world positions, exact to 0.0078 at 1e5, against cube texels and
// ray offsets of a few thousandths of a unit here (measured: at most 32; before, up to 347).
constexpr int kShadedPixels = kWidth * kHeight / 300;

void expect_same_picture(const Picture& original, const Picture& copy, const std::string& what) {
  const ImageDifference final_image = image_difference(original.final, copy.final);
  const ImageDifference depth = image_difference(original.depth, copy.depth);
  const ImageDifference normals = image_difference(original.normals, copy.normals);
  EXPECT_LE(final_image.pixels, kShadedPixels) << what << ", final image: " << final_image.text();
  EXPECT_LE(depth.pixels, kEdgePixels) << what << ", depth view: " << depth.text();
  EXPECT_LE(normals.pixels, kEdgePixels) << what << ", normals view: " << normals.text();
}

using FarFromOriginTest = glint::testing::GlTest;

struct Case {
  const char* name;
  ReflectionMode reflections;
  ShadowMethod shadows;
  GBufferMethod gbuffer;
  PrimaryVisibility primary;
};

TEST_F(FarFromOriginTest, SmallRoomMovedFarRendersTheSamePicture) {
  const Scene room = small_room();
  const FrameState frame = room_frame();
  const Case cases[] = {
      {"reflections off, cube shadows", ReflectionMode::off, ShadowMethod::cube, GBufferMethod::raster,
       PrimaryVisibility::raster},
      {"hybrid, rt shadows", ReflectionMode::hybrid, ShadowMethod::rt, GBufferMethod::raster, PrimaryVisibility::raster},
      {"hybrid, visibility G-buffer, compute rasteriser", ReflectionMode::hybrid, ShadowMethod::cube,
       GBufferMethod::visibility, PrimaryVisibility::compute},
      {"ssr, visibility G-buffer, rt primary", ReflectionMode::ssr, ShadowMethod::hybrid, GBufferMethod::visibility,
       PrimaryVisibility::rt},
  };
  for (const Case& c : cases) {
    FramePipelineSettings settings;
    settings.reflections = c.reflections;
    settings.shadows.method = c.shadows;
    settings.raster.gbuffer = c.gbuffer;
    settings.raster.primary = c.primary;
    const Picture original = render(room, frame, settings);
    for (const vec3 offset : kOffsets) {
      const std::string what = std::string(c.name) + ", moved by (" + std::to_string(offset.x) + ", " +
                                std::to_string(offset.y) + ", " + std::to_string(offset.z) + ")";
      expect_same_picture(original, render(transformed(room, 1.0f, offset), testing::moved(frame, offset), settings),
                          what);
    }
  }
}

// The atrium (frame 2100, the floor reflecting the hall), hybrid reflections, moved far away: 19 %
// of its pixels changed before.
TEST_F(FarFromOriginTest, AtriumMovedFarRendersTheSamePicture) {
  const Scene atrium = make_preset("atrium-simple");
  FramePipelineSettings settings;
  settings.reflections = ReflectionMode::hybrid;
  const FrameState frame = WalkthroughAnimation(atrium).at(2100);
  const Picture original = render(atrium, frame, settings);
  const vec3 offset(1.0e5f, 0.0f, -3.0e4f);
  const Scene far = transformed(atrium, 1.0f, offset);
  const Picture copy = render(far, WalkthroughAnimation(far).at(2100), settings);
  // The atrium's coordinates (0.1 and such) round when moved, so its copy is not quite the same
  // geometry, and its fine detail (creatures, columns' edges) shows it. Depth: the scaled copies'
  // allowance (scene_reflection_fade_test.cpp), 1 % of the pixels (measured 13; before, 571). The
  // final image: 5 % (measured 473, 3.3 %; before, 2176): shading far from the origin still reads
  // world positions stored in float (docs/render.md).
  const ImageDifference depth = image_difference(original.depth, copy.depth);
  EXPECT_LE(depth.pixels, kWidth * kHeight / 100) << depth.text();
  const ImageDifference final_image = image_difference(original.final, copy.final);
  EXPECT_LE(final_image.pixels, kWidth * kHeight / 20) << final_image.text();
}

// Secondary rays start off their surface by a share of the scene's size, and far from the origin by
// at least a few float steps of its coordinates, which positions there are only exact to.
TEST(RayOriginOffset, CoversTheFloatStepsOfTheScenesCoordinates) {
  const Aabb room{vec3(-4.0f, 0.0f, -4.0f), vec3(4.0f, 3.0f, 4.0f)};
  const float diagonal = glm::length(room.extent());
  EXPECT_EQ(ray_origin_offset(1e-4f, room), 1e-4f * diagonal) << "at the origin: the share of the size, exactly";
  const Aabb far{room.min + vec3(1.0e5f, 0.0f, 0.0f), room.max + vec3(1.0e5f, 0.0f, 0.0f)};
  const float step = 1.0e5f * 1.1920929e-7f;  // one float step at 1e5
  EXPECT_GE(ray_origin_offset(1e-4f, far), 4.0f * step);
  EXPECT_LE(ray_origin_offset(1e-4f, far), 16.0f * step);
  EXPECT_EQ(ray_origin_offset(0.0f, far), 0.0f) << "no offset asked for";
  EXPECT_EQ(ray_origin_offset(1e-4f, Aabb{}), 1e-4f) << "an empty scene: as for a diagonal of 1";
}

}  // namespace
}  // namespace glint::render
