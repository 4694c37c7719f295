// Ray-traced primary visibility (--primary rt, PrimaryRayPass): the camera rays' closest hits give
// the visibility ids the id draw gives (VisibilityIdPass) on every pixel whose centre is not within
// 1/64 pixel of an edge of either triangle (the rasteriser snaps corners to a sub-pixel grid, see
// tests/render/visibility_gbuffer_test.cpp), the resolve then rebuilds the same G-buffer there, the
// rays run through the pixel centres, and whole frames are nearly equal.
#include "cuda/device_query.h"
#include "backends/registry.h"
#include "metrics/rmse_psnr.h"
#include "render/frame_pipeline.h"
#include "render/visibility_id_pass.h"
#include "rt/ray_tracer.h"
#include "scene/presets.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace glint::render {
namespace {

using PrimaryRayPassTest = testing::GlTest;

constexpr int kWidth = 160;
constexpr int kHeight = 90;
constexpr float kEdgeTolerancePixels = 1.0f / 64.0f;

FramePipelineSettings primary_settings(PrimaryVisibility primary, const std::string& backend) {
  FramePipelineSettings settings;
  settings.reflections = ReflectionMode::off;
  settings.raster.gbuffer = GBufferMethod::visibility;
  settings.raster.primary = primary;
  settings.ray_tracing.backend = backend;
  return settings;
}

struct Frame {
  std::vector<glm::uvec2> ids;  // top row first
  ImageRgbaF albedo, position, normal, material;
  FrameConstants constants;
};

Frame render_frame(const Scene& scene, const FrameState& state, PrimaryVisibility primary, const std::string& backend) {
  FramePipeline pipeline(scene, kWidth, kHeight, primary_settings(primary, backend));
  pipeline.render(state);
  const RasterPipeline& raster = pipeline.raster();
  EXPECT_EQ(raster.primary_rays() != nullptr, primary == PrimaryVisibility::rt);
  return {read_visibility_ids(raster.visibility_id(), kWidth, kHeight),
          raster.read_rgbaf(RasterOutput::AlbedoReflectivity),
          raster.read_rgbaf(RasterOutput::WorldPosition),
          raster.read_rgbaf(RasterOutput::WorldNormalRoughness),
          raster.read_rgbaf(RasterOutput::MaterialId),
          raster.frame_constants()};
}

// Pixel-space distance from `point` to the nearest edge of the triangle that id `id` names (top
// row first, pixel centres at integers); a large value for the background or for a triangle with a
// corner behind the camera (its projection is not a triangle).
float distance_to_edges(const Scene& scene, const FrameConstants& constants, glm::uvec2 id, vec2 point) {
  if (id.x == 0u || id.x > scene.instances.size()) return 1e30f;
  const Instance& instance = scene.instances[id.x - 1u];
  const Mesh& mesh = scene.meshes[instance.mesh];
  if (3u * id.y + 2u >= mesh.indices.size()) return 1e30f;
  vec2 corner[3];
  for (unsigned i = 0; i < 3; ++i) {
    const vec4 clip = constants.view_projection * instance.transform * vec4(mesh.positions[mesh.indices[3u * id.y + i]], 1.0f);
    if (clip.w <= 0.0f) return 1e30f;
    const vec2 ndc = vec2(clip) / clip.w;
    corner[i] = vec2((ndc.x * 0.5f + 0.5f) * static_cast<float>(constants.viewport.x) - 0.5f,
                     (0.5f - ndc.y * 0.5f) * static_cast<float>(constants.viewport.y) - 0.5f);
  }
  float nearest = 1e30f;
  for (int i = 0; i < 3; ++i) {
    const vec2 a = corner[i], b = corner[(i + 1) % 3];
    const float t = glm::clamp(glm::dot(point - a, b - a) / std::max(glm::dot(b - a, b - a), 1e-30f), 0.0f, 1.0f);
    nearest = std::min(nearest, glm::length(point - (a + t * (b - a))));
  }
  return nearest;
}

struct IdComparison {
  int geometry = 0;       // pixels the id draw covers
  int different = 0;      // ids differ
  int unexplained = 0;    // ... with the centre not within kEdgeTolerancePixels of either triangle's edge
  int gbuffer = 0;        // equal ids, but a G-buffer texel differs
};

IdComparison compare(const Scene& scene, const Frame& raster, const Frame& traced) {
  IdComparison c;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y * kWidth + x);
      const glm::uvec2 a = raster.ids[i], b = traced.ids[i];
      c.geometry += a.x != 0u;
      if (a == b) {
        // The resolve rebuilds every image from the id alone: the same id gives the same texels.
        c.gbuffer += raster.albedo.at(x, y) != traced.albedo.at(x, y) || raster.position.at(x, y) != traced.position.at(x, y) ||
                     raster.normal.at(x, y) != traced.normal.at(x, y) || raster.material.at(x, y) != traced.material.at(x, y);
        continue;
      }
      ++c.different;
      const vec2 centre(static_cast<float>(x), static_cast<float>(y));
      const float edge = std::min(distance_to_edges(scene, raster.constants, a, centre),
                                  distance_to_edges(scene, raster.constants, b, centre));
      c.unexplained += edge > kEdgeTolerancePixels;
    }
  std::printf("[ primary rt ] %d geometry pixels, %d ids differ (%d not near an edge), %d G-buffer differences\n",
              c.geometry, c.different, c.unexplained, c.gbuffer);
  return c;
}

TEST_F(PrimaryRayPassTest, IdsEqualTheIdDrawAwayFromTriangleEdges) {
  const Scene scene = make_preset("atrium-simple");
  const WalkthroughAnimation animation(scene);
  for (const char* backend : {"cpu", "embree"})
    for (const int frame : {2100, 4400}) {
      SCOPED_TRACE(::testing::Message() << backend << ", atrium-simple frame " << frame);
      const Frame raster = render_frame(scene, animation.at(frame), PrimaryVisibility::raster, backend);
      const Frame traced = render_frame(scene, animation.at(frame), PrimaryVisibility::rt, backend);
      const IdComparison c = compare(scene, raster, traced);
      EXPECT_GT(c.geometry, kWidth * kHeight / 2);
      EXPECT_EQ(c.unexplained, 0);
      EXPECT_LE(c.different, c.geometry / 50);  // edges only
      EXPECT_EQ(c.gbuffer, 0);
    }
}

// Ray i is pixel (i % width, i / width) in GL order, starts on the near plane and ends on the far
// plane (t in [0, 1]; clip w is the view depth), and passes through the pixel centre.
TEST_F(PrimaryRayPassTest, RaysRunThroughThePixelCentresFromNearToFar) {
  const Scene scene = make_preset("atrium-simple");
  const FrameState state = WalkthroughAnimation(scene).at(2100);
  FramePipeline pipeline(scene, kWidth, kHeight, primary_settings(PrimaryVisibility::rt, "embree"));
  pipeline.render(state);
  const PrimaryRayPass* primary = pipeline.raster().primary_rays();
  ASSERT_NE(primary, nullptr);
  const std::span<const accel::Ray> rays = primary->rays();
  ASSERT_EQ(rays.size(), static_cast<std::size_t>(kWidth * kHeight));
  const FrameConstants& constants = pipeline.raster().frame_constants();
  // Pixel-space distance of a point of the ray from the pixel centre, and the clip distance
  // (view-space depth) of its ends from the near and far planes, relative to those distances.
  float worst_pixels = 0.0f, worst_near = 0.0f, worst_far = 0.0f;
  int bad_interval = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const accel::Ray& ray = rays[static_cast<std::size_t>(y * kWidth + x)];
      bad_interval += ray.t_min != 0.0f || ray.t_max != 1.0f;
      for (const float t : {0.0f, 0.5f, 1.0f}) {
        const vec4 clip = constants.view_projection * vec4(ray.origin + t * ray.direction, 1.0f);
        const vec2 pixel = (vec2(clip) / clip.w * 0.5f + 0.5f) * vec2(kWidth, kHeight) - 0.5f;
        worst_pixels = std::max(worst_pixels, glm::length(pixel - vec2(x, y)));
        if (t == 0.0f) worst_near = std::max(worst_near, std::abs(clip.w / constants.near_far.x - 1.0f));
        if (t == 1.0f) worst_far = std::max(worst_far, std::abs(clip.w / constants.near_far.y - 1.0f));
      }
    }
  std::printf("[ primary rt ] rays: worst %.3g px from the centre, near %.3g, far %.3g\n",
              static_cast<double>(worst_pixels), static_cast<double>(worst_near), static_cast<double>(worst_far));
  EXPECT_EQ(bad_interval, 0);
  // Float unprojection through a far plane thousands of near distances away: 0.0057 px measured
  // (llvmpipe, 2026-11-25); a ray off by half a pixel (corner instead of centre) is 0.5.
  EXPECT_LT(worst_pixels, kEdgeTolerancePixels);
  EXPECT_LT(worst_near, 1e-3f);
  EXPECT_LT(worst_far, 1e-3f);
  // The hits are the tracer's closest hits of those rays.
  const std::span<const accel::Hit> hits = primary->hits();
  const std::unique_ptr<rt::RayTracer> reference = backends::make_ray_tracer("cpu");
  reference->build(scene, {});
  std::vector<accel::Hit> expected(rays.size());
  reference->trace_closest(rays, expected);
  int hit_mismatches = 0;
  for (std::size_t i = 0; i < rays.size(); ++i)
    hit_mismatches += hits[i].instance != expected[i].instance || hits[i].prim != expected[i].prim;
  EXPECT_LE(hit_mismatches, static_cast<int>(rays.size() / 200)) << "cpu and embree closest hits";
}

// A whole frame (SSR, hybrid reflections and shadows, resolve) with either primary visibility.
// Ids differ only on triangle edges (where the shading of neighbouring triangles usually agrees) and
// the rest of the frame reads only the G-buffer: 43.5 dB measured (llvmpipe, embree, 160x90, frame
// 2100, 2026-11-25); bound 40 dB.
TEST_F(PrimaryRayPassTest, FrameWithRayTracedPrimaryVisibilityIsNearlyTheSame) {
  const Scene scene = make_preset("atrium-simple");
  const FrameState state = WalkthroughAnimation(scene).at(2100);
  const auto render_final = [&](PrimaryVisibility primary) {
    FramePipelineSettings settings = primary_settings(primary, "embree");
    settings.reflections = ReflectionMode::hybrid;
    FramePipeline pipeline(scene, kWidth, kHeight, settings);
    pipeline.render(state);
    return pipeline.read_final();
  };
  const ImageRgba8 raster = render_final(PrimaryVisibility::raster);
  const ImageRgba8 traced = render_final(PrimaryVisibility::rt);
  const double psnr = metrics::rmse_psnr(traced, raster).psnr;
  std::printf("[ primary rt ] final frame: PSNR %.2f dB against the id draw's\n", psnr);
  EXPECT_GE(psnr, 40.0);
}

TEST_F(PrimaryRayPassTest, GpuBackendIdsEqualTheIdDrawAwayFromTriangleEdges) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const Scene scene = make_preset("atrium-simple");
  const FrameState state = WalkthroughAnimation(scene).at(2100);
  const Frame raster = render_frame(scene, state, PrimaryVisibility::raster, "cpu");
  std::vector<std::string> backends = {"cuda"};
  if (GLINT_HAVE_OPTIX) backends.push_back("optix");
  for (const std::string& backend : backends) {
    SCOPED_TRACE(backend);
    const IdComparison c = compare(scene, raster, render_frame(scene, state, PrimaryVisibility::rt, backend));
    EXPECT_EQ(c.unexplained, 0);
    EXPECT_EQ(c.gbuffer, 0);
  }
}

TEST(PrimaryVisibilitySettings, NamesRoundTripAndRtNeedsTheVisibilityGBuffer) {
  EXPECT_EQ(parse_primary_visibility("rt"), PrimaryVisibility::rt);
  EXPECT_EQ(primary_visibility_name(PrimaryVisibility::raster), "raster");
  EXPECT_THROW(parse_primary_visibility("raytraced"), Error);
  RasterSettings settings;
  settings.primary = PrimaryVisibility::rt;
  EXPECT_THROW(settings.validate(), Error);  // with the raster G-buffer
  settings.gbuffer = GBufferMethod::visibility;
  EXPECT_NO_THROW(settings.validate());
  FramePipelineSettings frame;
  frame.raster = settings;
  frame.reflections = ReflectionMode::off;
  EXPECT_TRUE(uses_ray_tracer(frame));  // the tracer is built for the primary rays alone
}

}  // namespace
}  // namespace glint::render
