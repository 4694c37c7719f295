// Motion of the deforming meshes (render/surface_motion.h, docs/glossy.md): both G-buffer methods
// write each pixel's world displacement since the previous frame, the reflection denoiser reprojects
// a moved surface to where that surface point was, and static geometry keeps exactly the result it
// had without surface motion.
#include "gl/gl_test_context.h"
#include "raster_test_scene.h"
#include "render/frame_pipeline.h"
#include "render/raster_pipeline.h"
#include "render/reflection_denoiser.h"
#include "render/reflection_sampling.h"
#include "render/render_targets.h"
#include "render/surface_motion.h"
#include "synthetic_gbuffer.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace glint {
namespace {

using render::GBufferMethod;
using render::RasterPipeline;
using render::ReflectionDenoiser;

constexpr int kWidth = 64;
constexpr int kHeight = 48;

// A rough reflective floor and, above it, a rough reflective plate whose mesh deforms: its instance
// scales by 1.25 and shifts, so the world motion is the transform's linear part times the object
// displacement.
struct PlateScene {
  Scene scene;
  std::uint32_t plate_mesh = 0;
  mat4 plate_transform{1.0f};
};

PlateScene plate_over_floor() {
  PlateScene s;
  s.scene = testing::make_empty_test_scene(vec3(0.0f, 4.0f, 1.0f));
  const std::uint32_t floor = testing::add_material(s.scene, vec3(0.5f), 0.5f);
  const std::uint32_t plate = testing::add_material(s.scene, vec3(0.3f, 0.4f, 0.6f), 0.5f);
  s.scene.materials[floor].roughness = 0.5f;
  s.scene.materials[plate].roughness = 0.5f;
  testing::add_quad(s.scene, vec3(-20.0f, 0.0f, 20.0f), vec3(40.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -40.0f), floor);
  s.plate_mesh =
      testing::add_quad(s.scene, vec3(-1.0f, 0.5f, 1.0f), vec3(2.0f, 0.0f, 0.0f), vec3(0.0f, 0.0f, -2.0f), plate);
  s.scene.meshes[s.plate_mesh].deformable = true;
  s.scene.meshes[s.plate_mesh].deform = SineDeform{};
  s.plate_transform = glm::scale(glm::translate(mat4(1.0f), vec3(0.2f, 0.0f, 0.0f)), vec3(1.25f));
  s.scene.instances.back().transform = s.plate_transform;
  return s;
}

FrameState camera(vec3 eye) { return testing::look_at(eye, vec3(0.0f), vec3(0.0f, 4.0f, 1.0f)); }

// Moves the plate's vertices (object space) by `delta` on the GPU, as a deformer's upload does.
void move_plate(RasterPipeline& raster, const PlateScene& s, vec3 delta) {
  std::vector<vec3> positions = s.scene.meshes[s.plate_mesh].positions;
  for (vec3& p : positions) p += delta;
  raster.gpu_scene().update_mesh_vertices(s.plate_mesh, positions, s.scene.meshes[s.plate_mesh].normals);
}

render::ResolveSettings denoise_settings() {
  render::ResolveSettings settings;
  settings.fade_end = 0.0f;
  settings.denoise = true;
  return settings;
}

// One frame's G-buffer, glossy on in its frame constants.
void render_frame(RasterPipeline& raster, const FrameState& frame) {
  raster.render(frame);
  render::ReflectionSamplingSettings glossy;
  glossy.glossy = true;
  render::write_reflection_sampling(raster.frame_constants_buffer(), glossy, 0);
}

// A denoiser run over that frame, with the pipeline's world motion or without it (camera only).
void denoise(const RasterPipeline& raster, const GlTexture& reflection, ReflectionDenoiser& denoiser,
             bool with_motion) {
  denoiser.run({reflection.id(), raster.world_position(), raster.world_normal_roughness(), raster.albedo_reflectivity(),
                raster.frame_constants_buffer(), raster.frame_constants().view_projection,
                with_motion ? raster.world_motion() : 0},
               denoise_settings());
}

GlTexture constant_reflection() {
  return render::testing::upload_rgba(render::kReflectionFormat, kWidth, kHeight,
                                      std::vector<vec4>(kWidth * kHeight, vec4(0.5f, 0.5f, 0.5f, 1.0f)));
}

class SurfaceMotionTest : public glint::testing::GlTest, public ::testing::WithParamInterface<GBufferMethod> {
protected:
  RasterPipeline make_raster(const Scene& scene) const {
    render::RasterSettings settings;
    settings.gbuffer = GetParam();
    settings.surface_motion = true;
    return RasterPipeline(scene, kWidth, kHeight, settings);
  }
};

TEST_P(SurfaceMotionTest, DeformedPlateReprojectsToWhereItsSurfaceWas) {
  const PlateScene s = plate_over_floor();
  RasterPipeline raster = make_raster(s.scene);
  const FrameState frame = camera(vec3(0.0f, 3.5f, 4.5f));  // a still camera: only the plate moves
  const GlTexture reflection = constant_reflection();
  ReflectionDenoiser with_motion(kWidth, kHeight), camera_only(kWidth, kHeight);
  with_motion.record_motion(true);
  camera_only.record_motion(true);

  render_frame(raster, frame);
  denoise(raster, reflection, with_motion, true);
  denoise(raster, reflection, camera_only, false);
  const std::vector<vec4> before = render::testing::read_rgba_float(raster.world_position(), kWidth, kHeight);
  const vec3 delta(0.12f, 0.2f, -0.08f);  // object space; up by 0.25 in the world, far beyond the plane tolerance
  move_plate(raster, s, delta);
  render_frame(raster, frame);
  denoise(raster, reflection, with_motion, true);
  denoise(raster, reflection, camera_only, false);

  const std::vector<vec4> position = render::testing::read_rgba_float(raster.world_position(), kWidth, kHeight);
  const std::vector<vec4> world_motion = render::testing::read_rgba_float(raster.world_motion(), kWidth, kHeight);
  const std::vector<vec2> motion = with_motion.read_motion();
  const std::vector<vec2> camera_motion = camera_only.read_motion();
  const std::vector<vec4> history = render::testing::read_rgba_float(with_motion.accumulated(), kWidth, kHeight);
  const std::vector<vec4> camera_history = render::testing::read_rgba_float(camera_only.accumulated(), kWidth, kHeight);
  const vec3 world_delta = glm::mat3(s.plate_transform) * delta;
  const render::FrameConstants& constants = raster.frame_constants();

  int plate = 0, plate_mapped = 0, plate_mapped_camera_only = 0, floor_still = 0, floor_uncovered = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      if (position[i].w == 0.0f) continue;
      const vec3 world(position[i]);
      if (world.y > 0.25f) {  // the plate (at 0.5 + 0.25 now)
        ++plate;
        // The G-buffer's motion: previous minus current world position, the same for every point.
        ASSERT_NEAR(world_motion[i].x, -world_delta.x, 1e-3f) << x << "," << y;
        ASSERT_NEAR(world_motion[i].y, -world_delta.y, 1e-3f) << x << "," << y;
        ASSERT_NEAR(world_motion[i].z, -world_delta.z, 1e-3f) << x << "," << y;
        if (camera_motion[i].x >= 0.0f) ++plate_mapped_camera_only;
        if (motion[i].x < 0.0f) continue;
        ++plate_mapped;
        // Analytic: this surface point before the move, seen by the (same) camera.
        const vec2 expected = render::testing::project_to_pixels(constants, world - world_delta);
        ASSERT_NEAR(motion[i].x, expected.x, 0.01f) << x << "," << y;
        ASSERT_NEAR(motion[i].y, expected.y, 0.01f) << x << "," << y;
        EXPECT_EQ(history[i].w, 2.0f) << "the plate keeps its history at " << x << "," << y;
        EXPECT_EQ(camera_history[i].w, 1.0f) << "camera motion alone restarts it at " << x << "," << y;
      } else {
        // The static floor: exactly no motion of its own, and a still camera maps it onto itself.
        ASSERT_EQ(world_motion[i].x, 0.0f);
        ASSERT_EQ(world_motion[i].y, 0.0f);
        ASSERT_EQ(world_motion[i].z, 0.0f);
        ASSERT_EQ(motion[i], camera_motion[i]) << x << "," << y;
        if (before[i].y > 0.25f) {
          // Covered by the plate last frame: disoccluded, the history restarts.
          EXPECT_EQ(motion[i].x, -1.0f) << x << "," << y;
          ++floor_uncovered;
        } else {
          EXPECT_NEAR(motion[i].x, static_cast<float>(x) + 0.5f, 1e-3f) << x << "," << y;
          EXPECT_NEAR(motion[i].y, static_cast<float>(y) + 0.5f, 1e-3f) << x << "," << y;
          ++floor_still;
        }
      }
    }
  EXPECT_GT(plate, 150);
  EXPECT_GT(floor_still, 500);
  EXPECT_GT(floor_uncovered, 10) << "the plate moved off some floor pixels";
  EXPECT_GT(plate_mapped, plate * 8 / 10) << "most of the plate was plate last frame";
  EXPECT_EQ(plate_mapped_camera_only, 0) << "without its motion the lifted plate fails the same-surface test";
}

TEST_P(SurfaceMotionTest, StaticGeometryKeepsExactlyTheCameraOnlyResult) {
  // The plate's mesh is deformable but does not move; the camera does.
  const PlateScene s = plate_over_floor();
  RasterPipeline raster = make_raster(s.scene);
  const GlTexture reflection = constant_reflection();
  ReflectionDenoiser with_motion(kWidth, kHeight), camera_only(kWidth, kHeight);
  with_motion.record_motion(true);
  camera_only.record_motion(true);
  const vec3 eyes[3] = {vec3(0.0f, 3.5f, 4.5f), vec3(0.3f, 3.4f, 4.4f), vec3(0.5f, 3.2f, 4.6f)};
  for (const vec3& eye : eyes) {
    render_frame(raster, camera(eye));
    denoise(raster, reflection, with_motion, true);
    denoise(raster, reflection, camera_only, false);
  }
  for (const vec4& m : render::testing::read_rgba_float(raster.world_motion(), kWidth, kHeight))
    ASSERT_EQ(vec3(m), vec3(0.0f));
  EXPECT_EQ(with_motion.read_motion(), camera_only.read_motion());
  EXPECT_EQ(render::testing::read_rgba16f_bits(with_motion.output(), kWidth, kHeight),
            render::testing::read_rgba16f_bits(camera_only.output(), kWidth, kHeight));
}

INSTANTIATE_TEST_SUITE_P(BothGBufferMethods, SurfaceMotionTest,
                         ::testing::Values(GBufferMethod::raster, GBufferMethod::visibility),
                         [](const ::testing::TestParamInfo<GBufferMethod>& param) {
                           return std::string(render::gbuffer_method_name(param.param));
                         });

using SurfaceMotionPipelineTest = glint::testing::GlTest;

TEST_F(SurfaceMotionPipelineTest, MadeOnlyForTheDenoiser) {
  const PlateScene s = plate_over_floor();
  render::FramePipelineSettings settings;
  EXPECT_EQ(render::FramePipeline(s.scene, kWidth, kHeight, settings).raster().world_motion(), 0u);
  settings.resolve.denoise = true;
  EXPECT_NE(render::FramePipeline(s.scene, kWidth, kHeight, settings).raster().world_motion(), 0u);
}

}  // namespace
}  // namespace glint
