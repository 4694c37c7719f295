// The lit image against a CPU evaluation of the documented lighting formula (shaders/lighting.frag.glsl)
// from the same G-buffer and shadow mask, on every pixel: lit, shadowed, emissive and sky.
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

// The formula of lighting.frag.glsl, written independently on the CPU.
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

TEST_F(LightingPass, EveryPixelMatchesTheFormulaAndShadowLeavesAmbientOnly) {
  std::vector<testing::QuadGeometry> occluders;
  const Scene scene = testing::make_floor_with_occluders(occluders);
  render::RasterSettings settings;
  settings.ambient_fraction = 0.2f;
  RasterPipeline raster(scene, kWidth, kHeight, settings);
  // Looking slightly down from above the floor: the far floor and the sky above the horizon show.
  const vec3 eye(0.0f, 6.0f, 12.0f);
  raster.render(testing::look_at(eye, vec3(0.0f, 0.0f, -4.0f), scene.light.position));
  const ImageRgbaF albedo = raster.read_rgbaf(RasterOutput::AlbedoReflectivity);
  const ImageRgbaF position = raster.read_rgbaf(RasterOutput::WorldPosition);
  const ImageRgbaF normal = raster.read_rgbaf(RasterOutput::WorldNormalRoughness);
  const ImageRgbaF id = raster.read_rgbaf(RasterOutput::MaterialId);
  const ImageRgbaF mask = raster.read_rgbaf(RasterOutput::ShadowMask);
  const ImageRgbaF lit = raster.read_rgbaf(RasterOutput::Lit);

  int sky = 0, shadowed = 0, fully_lit = 0, emissive = 0, wrong = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      vec3 expected = scene.sky_color;
      const int material_id = static_cast<int>(id.at(x, y).x);
      if (material_id == 0) {
        ++sky;
      } else {
        const Material& material = scene.materials[static_cast<std::size_t>(material_id - 1)];
        const float shadow = mask.at(x, y).x;
        expected = expected_radiance(scene, material, settings, eye, scene.light.position, vec3(albedo.at(x, y)),
                                     vec3(position.at(x, y)), vec3(normal.at(x, y)), shadow);
        if (shadow == 0.0f) {
          ++shadowed;
          // In full shadow only ambient and emissive remain.
          const vec3 ambient = settings.ambient_fraction * scene.sky_color * vec3(albedo.at(x, y)) + material.emissive;
          if (glm::length(expected - ambient) > 1e-6f) ++wrong;
        }
        fully_lit += shadow == 1.0f;
        emissive += material.emissive != vec3(0.0f);
      }
      const vec3 got(lit.at(x, y));
      // RGBA16F keeps about 3 decimal digits.
      if (glm::any(glm::greaterThan(glm::abs(got - expected), 2e-3f + 2e-3f * glm::abs(expected))) ||
          lit.at(x, y).w != 1.0f) {
        if (++wrong <= 5)
          ADD_FAILURE() << "pixel (" << x << ", " << y << ") id " << material_id << ": got (" << got.x << ", " << got.y
                        << ", " << got.z << "), expected (" << expected.x << ", " << expected.y << ", " << expected.z
                        << ")";
      }
    }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(sky, 50);
  EXPECT_GT(shadowed, 30);
  EXPECT_GT(fully_lit, 1000);
  EXPECT_GT(emissive, 5);
}

}  // namespace
}  // namespace glint
