// The lit image against a CPU evaluation of the documented lighting formula (shaders/lighting.comp.glsl)
// from the same G-buffer and shadow mask, on every pixel: lit, shadowed, emissive and sky; and on the
// border of an image whose size is no multiple of the compute pass's 8 x 8 work groups.
#include "gl/gl_test_context.h"
#include "raster_test_scene.h"
#include "render/raster_pipeline.h"

#include <gtest/gtest.h>

#include <cmath>

namespace glint {
namespace {

using render::RasterOutput;
using render::RasterPipeline;
using LightingPass = testing::GlTest;

constexpr int kWidth = 96, kHeight = 64;
constexpr float kPi = 3.14159265358979f;

// The formula of lighting.comp.glsl, written independently on the CPU.
vec3 expected_radiance(const Scene& scene, const Material& material, const render::RasterSettings& settings,
                       vec3 camera, vec3 light, vec3 albedo, vec3 position, vec3 normal, float shadow) {
  vec3 n = glm::normalize(normal);
  const vec3 v = glm::normalize(camera - position);
  if (glm::dot(n, v) < 0.0f) n = -n;
  const float d = glm::length(light - position);
  const vec3 l = (light - position) / d;
  const float n_dot_l = std::max(glm::dot(n, l), 0.0f);
  const float attenuation = scene.light.intensity / (1.0f + (d / scene.light.range) * (d / scene.light.range));
  const vec3 irradiance = scene.light.color * attenuation * n_dot_l * shadow;
  const vec3 h = glm::normalize(l + v);
  const float e = material.specular_exponent;
  const float specular = n_dot_l > 0.0f ? (e + 8.0f) / (8.0f * kPi) * std::pow(std::max(glm::dot(n, h), 0.0f), e) : 0.0f;
  return irradiance * (albedo / kPi + material.specular * specular) + settings.ambient_fraction * scene.sky_color * albedo +
         material.emissive;
}

// One frame of the occluder scene at width x height with ambient 0.2, looking slightly down from above
// the floor: the far floor and the sky above the horizon show. Keeps what the lighting pass read and
// wrote, read back.
struct LitFrame {
  LitFrame(int width, int height) : scene(testing::make_floor_with_occluders(occluders)) {
    settings.ambient_fraction = 0.2f;
    RasterPipeline raster(scene, width, height, settings);
    raster.render(testing::look_at(eye, vec3(0.0f, 0.0f, -4.0f), scene.light.position));
    albedo = raster.read_rgbaf(RasterOutput::AlbedoReflectivity);
    position = raster.read_rgbaf(RasterOutput::WorldPosition);
    normal = raster.read_rgbaf(RasterOutput::WorldNormalRoughness);
    id = raster.read_rgbaf(RasterOutput::MaterialId);
    mask = raster.read_rgbaf(RasterOutput::ShadowMask);
    lit = raster.read_rgbaf(RasterOutput::Lit);
  }

  int material_id(int x, int y) const { return static_cast<int>(id.at(x, y).x); }
  const Material& material(int x, int y) const {
    return scene.materials[static_cast<std::size_t>(material_id(x, y) - 1)];
  }

  // expected_radiance from the read-back G-buffer and mask at (x, y); the sky colour on background.
  vec3 expected_at(int x, int y) const {
    if (material_id(x, y) == 0) return scene.sky_color;
    return expected_radiance(scene, material(x, y), settings, eye, scene.light.position, vec3(albedo.at(x, y)),
                             vec3(position.at(x, y)), vec3(normal.at(x, y)), mask.at(x, y).x);
  }

  // Whether the lit pixel (x, y) is `expected` (RGBA16F keeps about 3 decimal digits) with a = 1;
  // the first five mismatches of a test (counted by `wrong`) are reported.
  bool matches(int x, int y, vec3 expected, int& wrong) const {
    const vec3 got(lit.at(x, y));
    if (!glm::any(glm::greaterThan(glm::abs(got - expected), 2e-3f + 2e-3f * glm::abs(expected))) &&
        lit.at(x, y).w == 1.0f)
      return true;
    if (++wrong <= 5)
      ADD_FAILURE() << "pixel (" << x << ", " << y << ") id " << material_id(x, y) << ": got (" << got.x << ", "
                    << got.y << ", " << got.z << "), expected (" << expected.x << ", " << expected.y << ", "
                    << expected.z << ")";
    return false;
  }

  std::vector<testing::QuadGeometry> occluders;
  Scene scene;
  render::RasterSettings settings;
  vec3 eye{0.0f, 6.0f, 12.0f};
  ImageRgbaF albedo, position, normal, id, mask, lit;
};

TEST_F(LightingPass, EveryPixelMatchesTheFormulaAndShadowLeavesAmbientOnly) {
  const LitFrame frame(kWidth, kHeight);
  const Scene& scene = frame.scene;

  int sky = 0, shadowed = 0, fully_lit = 0, emissive = 0, wrong = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const vec3 expected = frame.expected_at(x, y);
      if (frame.material_id(x, y) == 0) {
        ++sky;
      } else {
        const Material& material = frame.material(x, y);
        const float shadow = frame.mask.at(x, y).x;
        if (shadow == 0.0f) {
          ++shadowed;
          // In full shadow only ambient and emissive remain.
          const vec3 ambient =
              frame.settings.ambient_fraction * scene.sky_color * vec3(frame.albedo.at(x, y)) + material.emissive;
          if (glm::length(expected - ambient) > 1e-6f) ++wrong;
        }
        fully_lit += shadow == 1.0f;
        emissive += material.emissive != vec3(0.0f);
      }
      frame.matches(x, y, expected, wrong);
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(sky, 50);
  EXPECT_GT(shadowed, 30);
  EXPECT_GT(fully_lit, 1000);
  EXPECT_GT(emissive, 5);
}

// 37 x 23 is no multiple of the pass's 8 x 8 work groups: the partial groups at the right and top
// must write every pixel of the last column and row, each with its own pixel's value (and none
// outside the image). The whole border is checked (read-backs are top row first), sky and floor.
TEST_F(LightingPass, TheBorderOfAnImageOfPartialWorkGroupsMatchesTheFormula) {
  constexpr int w = 37, h = 23;
  const LitFrame frame(w, h);
  int sky = 0, surface = 0, wrong = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x != 0 && x != w - 1 && y != 0 && y != h - 1) continue;
      (frame.material_id(x, y) == 0 ? sky : surface) += 1;
      frame.matches(x, y, frame.expected_at(x, y), wrong);
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(sky, 10);  // the top row
  EXPECT_GT(surface, 30);
}

}  // namespace
}  // namespace glint
