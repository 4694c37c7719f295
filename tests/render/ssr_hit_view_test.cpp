// SSR's colour at a trusted hit is the hit as the reflecting surface sees it, as rt's hit shading
// shades it (docs/ssr.md "Where the hit is"): a glossy wall seen in a mirror strip shows its
// highlight where the reflected rays see it, not where the camera does.
#include "render/frame_pipeline.h"
#include "render/render_targets.h"
#include "render/ssr_pass.h"
#include "render/texture_readback.h"
#include "raster_test_scene.h"
#include "../gl/gl_test_context.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace glint::render {
namespace {

using SsrHitViewTest = testing::GlTest;

constexpr int kWidth = 96;
constexpr int kHeight = 64;

// mirror_strip_before_wall (every reflected ray meets the wall on screen) with a glossy wall: white
// specular colour, exponent 64. The camera and the strip see a wall point at different angles to the
// light's mirror direction, so its highlight differs between the two views.
Scene glossy_wall_in_a_mirror_strip() {
  Scene scene = testing::mirror_strip_before_wall();
  for (Material& material : scene.materials)
    if (material.reflectivity == 0.0f) {
      material.specular = vec3(1.0f);
      material.specular_exponent = 64.0f;
    }
  return scene;
}

FrameState camera_over_the_strip() {
  return testing::look_at(vec3(0.0f, 1.0f, 6.0f), vec3(0.0f, 1.0f, -4.0f), vec3(0.0f, 3.0f, 2.0f));
}

FramePipelineSettings settings_for(ReflectionMode mode) {
  FramePipelineSettings settings;
  settings.reflections = mode;
  settings.resolve.blur_radius = 0;
  settings.resolve.fade_end = 0.0f;
  settings.resolve.tone_map = ToneMap::none;
  return settings;
}

const DebugView& view_named(const std::vector<DebugView>& views, const std::string& name) {
  const auto it = std::find_if(views.begin(), views.end(), [&](const DebugView& v) { return v.name == name; });
  if (it == views.end()) throw std::runtime_error("no debug view " + name);
  return *it;
}

TEST_F(SsrHitViewTest, SsrsColourAtATrustedHitIsRtsHitShading) {
  const Scene scene = glossy_wall_in_a_mirror_strip();
  const FrameState frame = camera_over_the_strip();
  FramePipeline hybrid(scene, kWidth, kHeight, settings_for(ReflectionMode::hybrid));
  hybrid.render(frame);
  FramePipeline rt(scene, kWidth, kHeight, settings_for(ReflectionMode::rt));
  rt.render(frame);
  const std::vector<DebugView> hybrid_views = hybrid.read_debug_views();
  const std::vector<DebugView> rt_views = rt.read_debug_views();
  const ImageRgbaF& ssr = view_named(hybrid_views, "ssr_reflection").linear;
  const ImageRgbaF& failed = view_named(hybrid_views, "failure_mask").linear;
  const ImageRgbaF& traced = view_named(rt_views, "traced_reflection").linear;

  // Relative difference (largest channel) at every pixel SSR trusted, and how much the camera's
  // view would be off: the wall's highlight seen along the rays is brighter.
  int trusted = 0;
  double sum = 0.0, largest = 0.0, rt_luminance = 0.0, ssr_luminance = 0.0;
  for (std::size_t i = 0; i < ssr.pixels.size(); ++i) {
    const vec3 reference = vec3(traced.pixels[i]);
    if (failed.pixels[i].x != 0.0f || reference == vec3(0.0f)) continue;  // failed, or not reflective
    const vec3 colour = vec3(ssr.pixels[i]);
    const vec3 difference = glm::abs(colour - reference) / glm::max(reference, vec3(1e-3f));
    const double worst = std::max({difference.x, difference.y, difference.z});
    ++trusted;
    sum += worst;
    largest = std::max(largest, worst);
    rt_luminance += reference.y;
    ssr_luminance += colour.y;
  }
  ASSERT_GT(trusted, 150) << "the strip's reflections are SSR's";
  const double mean = sum / trusted;
  std::printf("%d trusted pixels: relative difference to rt mean %.5f, largest %.5f; mean green ssr %.4f rt %.4f\n",
              trusted, mean, largest, ssr_luminance / trusted, rt_luminance / trusted);
  // llvmpipe: mean 0.024, largest 0.095; with the camera's view of the hit (before) 0.80 and 2.07, the
  // reflection 13 % too bright on average (green 17.07 against rt's 15.15). What remains is the
  // highlight's change between the hit pixel's centre, where both views are evaluated, and the
  // points where lit_at interpolates and rt shades (0.007 and 0.021 with both views evaluated where
  // the ray meets the plane: docs/perf.md), and the lit image's half floats.
  EXPECT_LE(mean, 0.04);
  EXPECT_LE(largest, 0.15);
}

// The colour pass (SsrPass::shade, after a march()) and the single dispatch (run()) give the hits
// the same view, bit for bit, on real materials (SsrPassTest.MarchThenShadeEqualsOneDispatch does
// so on synthetic G-buffers, which have none). FramePipeline splits SSR only with a device backend.
TEST_F(SsrHitViewTest, MarchThenShadeEqualsOneDispatchWithMaterials) {
  const Scene scene = glossy_wall_in_a_mirror_strip();
  FramePipeline pipeline(scene, kWidth, kHeight, settings_for(ReflectionMode::ssr));
  pipeline.render(camera_over_the_strip());
  const RasterPipeline& raster = pipeline.raster();
  const SsrInputs inputs{raster.albedo_reflectivity(), raster.world_position(), raster.world_normal_roughness(),
                         raster.lit(),         raster.frame_constants_buffer(), raster.material_id(),
                         raster.shadow_mask(), raster.gpu_scene().material_buffer()};
  SsrPass one(kWidth, kHeight);
  one.run(inputs);
  SsrPass split(kWidth, kHeight);
  split.march(inputs);
  split.shade(inputs);
  const ImageRgbaF a = read_texture_rgbaf(one.reflection(), kReflectionFormat, kWidth, kHeight);
  const ImageRgbaF b = read_texture_rgbaf(split.reflection(), kReflectionFormat, kWidth, kHeight);
  int hits = 0;
  for (const vec4& p : a.pixels) hits += p.w > 0.0f;
  ASSERT_GT(hits, 150);
  EXPECT_EQ(a.pixels, b.pixels);
  // And the view changed something: without materials every hit keeps the camera's view.
  SsrInputs without_materials = inputs;
  without_materials.material_id = 0;
  SsrPass camera_view(kWidth, kHeight);
  camera_view.run(without_materials);
  const ImageRgbaF c = read_texture_rgbaf(camera_view.reflection(), kReflectionFormat, kWidth, kHeight);
  EXPECT_NE(a.pixels, c.pixels);
}

}  // namespace
}  // namespace glint::render
