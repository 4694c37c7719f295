// Embree as a reference backend must answer exactly the questions glint's own structures answer:
// same triangles, same interval semantics, same barycentric convention.
#include "rt/embree/embree_scene.h"

#include "accel/test_scenes.h"
#include "accel/builders/builder.h"
#include "accel/trace.h"
#include "support/error_of.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace glint::accel {
namespace {

using rt::embree_quality_name;
using rt::EmbreeDevice;
using rt::EmbreeQuality;
using rt::EmbreeScene;
using rt::kAllEmbreeQualities;
using rt::parse_embree_quality;
using testing::TestMesh;

// Embree runs its own (non-identical) triangle test, so t agrees to rounding, not bit for bit;
// another triangle at the same t is a tie (shared edge, duplicate) and accepted.
::testing::AssertionResult agrees(const Hit& expected, const Hit& actual) {
  if (expected.valid() != actual.valid())
    return ::testing::AssertionFailure() << (expected.valid() ? "missed prim " : "hit prim ")
                                         << (expected.valid() ? expected.prim : actual.prim);
  if (!expected.valid()) return ::testing::AssertionSuccess();
  if (std::abs(expected.t - actual.t) > 1e-4f * std::max(std::abs(expected.t), 1e-3f))
    return ::testing::AssertionFailure() << "t " << actual.t << " (prim " << actual.prim << ") instead of "
                                         << expected.t << " (prim " << expected.prim << ")";
  if (actual.instance != 0) return ::testing::AssertionFailure() << "instance " << actual.instance;
  return ::testing::AssertionSuccess();
}

struct Agreement {
  size_t rays = 0, hits = 0, disagreements = 0;
};

// Embree at `quality` against brute force and a SAH BVH (closest and any-hit), on `rays`.
Agreement compare(const EmbreeDevice& device, const TestMesh& mesh, const std::vector<Ray>& rays, EmbreeQuality quality) {
  const TriangleMesh view = mesh.view();
  const EmbreeScene scene(device, view, quality);
  const Bvh sah = build_bvh(BvhBuilder::sah, view);
  std::vector<Hit> embree_hits(rays.size()), sah_hits(rays.size());
  std::vector<uint8_t> occluded(rays.size());
  scene.trace_closest(rays, embree_hits);
  scene.trace_any(rays, occluded);
  trace_closest(sah, view, rays, sah_hits);
  Agreement agreement;
  agreement.rays = rays.size();
  for (size_t i = 0; i < rays.size(); ++i) {
    const Hit brute = testing::brute_force_closest(view, rays[i]);
    const auto versus_brute = agrees(brute, embree_hits[i]);
    const auto versus_sah = agrees(sah_hits[i], embree_hits[i]);
    if (!versus_brute || !versus_sah || (occluded[i] != 0) != brute.valid()) {
      if (++agreement.disagreements <= 5)
        ADD_FAILURE() << embree_quality_name(quality) << " ray " << i << ": " << versus_brute.message() << " / "
                      << versus_sah.message() << " / occluded " << int(occluded[i]);
    }
    agreement.hits += brute.valid() ? 1 : 0;
  }
  return agreement;
}

class EmbreeMatchesBruteForce : public ::testing::TestWithParam<EmbreeQuality> {};

TEST_P(EmbreeMatchesBruteForce, RandomSoup) {
  const EmbreeDevice device;
  const TestMesh soup = testing::make_random_soup(41, 3000);
  const Agreement a = compare(device, soup, testing::make_random_rays(soup, 42, 10000), GetParam());
  EXPECT_EQ(a.disagreements, 0u);
  EXPECT_GT(a.hits, a.rays / 4);  // the rays do test something
}

TEST_P(EmbreeMatchesBruteForce, GridEdgeAndVertexRaysAllHit) {
  const EmbreeDevice device;
  const TestMesh grid = testing::make_grid(24, true);
  const Agreement a = compare(device, grid, testing::make_grid_edge_rays(grid, 24, 43), GetParam());
  EXPECT_EQ(a.disagreements, 0u);
  EXPECT_EQ(a.hits, a.rays);
}

INSTANTIATE_TEST_SUITE_P(Accel, EmbreeMatchesBruteForce, ::testing::ValuesIn(kAllEmbreeQualities),
                         [](const auto& param_info) { return std::string(embree_quality_name(param_info.param)); });

TEST(EmbreeScene, BarycentricsFollowGlintsConvention) {
  // point = (1 - u - v) v0 + u v1 + v v2 must be the point origin + t * direction.
  const EmbreeDevice device;
  const TestMesh soup = testing::make_random_soup(44, 500);
  const TriangleMesh view = soup.view();
  const EmbreeScene scene(device, view, EmbreeQuality::medium);
  const std::vector<Ray> rays = testing::make_random_rays(soup, 45, 3000);
  std::vector<Hit> hits(rays.size());
  scene.trace_closest(rays, hits);
  size_t checked = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    if (!hits[i].valid()) continue;
    const Triangle tri = view.triangle(hits[i].prim);
    const vec3 from_uv = (1.0f - hits[i].u - hits[i].v) * tri.v0 + hits[i].u * tri.v1 + hits[i].v * tri.v2;
    const vec3 from_t = rays[i].origin + hits[i].t * rays[i].direction;
    const float scale = std::max(1.0f, glm::length(tri.bounds().extent()));
    EXPECT_LT(glm::length(from_uv - from_t), 1e-3f * scale) << "ray " << i;
    ++checked;
  }
  EXPECT_GT(checked, rays.size() / 4);
}

TEST(EmbreeScene, RayIntervalIsHonoured) {
  TestMesh mesh;
  for (float z : {1.0f, 2.0f, 3.0f}) {
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, -1, z), vec3(1, 1, z));
    mesh.add_triangle(vec3(-1, -1, z), vec3(1, 1, z), vec3(-1, 1, z));
  }
  const EmbreeDevice device;
  const EmbreeScene scene(device, mesh.view(), EmbreeQuality::high);
  const auto closest_t = [&](float t_min, float t_max) {
    const Ray ray{vec3(0.25f, 0.5f, 0.0f), t_min, vec3(0, 0, 1), t_max};
    Hit hit;
    scene.trace_closest(std::span(&ray, 1), std::span(&hit, 1));
    uint8_t occluded = 0;
    scene.trace_any(std::span(&ray, 1), std::span(&occluded, 1));
    EXPECT_EQ(occluded != 0, hit.valid());
    return hit.valid() ? hit.t : -1.0f;
  };
  EXPECT_FLOAT_EQ(closest_t(0.0f, kInfinity), 1.0f);
  EXPECT_FLOAT_EQ(closest_t(1.5f, kInfinity), 2.0f);
  EXPECT_FLOAT_EQ(closest_t(2.5f, 3.5f), 3.0f);
  EXPECT_EQ(closest_t(2.5f, 2.9f), -1.0f);
  EXPECT_EQ(closest_t(3.5f, kInfinity), -1.0f);
  EXPECT_EQ(closest_t(0.0f, 0.5f), -1.0f);
}

// Moves every vertex (a smooth wobble plus a shift) so the old boxes are wrong everywhere.
std::vector<vec3> moved(const std::vector<vec3>& positions) {
  std::vector<vec3> out = positions;
  for (vec3& p : out) p += vec3(0.3f * std::sin(p.y), 0.2f * std::cos(p.x), 0.5f);
  return out;
}

TEST(EmbreeScene, RefitAfterMovingVerticesEqualsAFreshBuild) {
  const EmbreeDevice device;
  TestMesh soup = testing::make_random_soup(46, 2000);
  EmbreeScene refitted(device, soup.view(), EmbreeQuality::refit);
  soup.positions = moved(soup.positions);
  refitted.update_vertices(soup.positions);
  const EmbreeScene fresh(device, soup.view(), EmbreeQuality::medium);
  const std::vector<Ray> rays = testing::make_random_rays(soup, 47, 8000);
  std::vector<Hit> refit_hits(rays.size()), fresh_hits(rays.size());
  refitted.trace_closest(rays, refit_hits);
  fresh.trace_closest(rays, fresh_hits);
  size_t hits = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    ASSERT_TRUE(agrees(fresh_hits[i], refit_hits[i])) << "ray " << i;
    ASSERT_TRUE(agrees(testing::brute_force_closest(soup.view(), rays[i]), refit_hits[i])) << "ray " << i;
    hits += fresh_hits[i].valid() ? 1 : 0;
  }
  EXPECT_GT(hits, rays.size() / 4);
  EXPECT_GE(refitted.update_ms(), 0.0);
}

TEST(EmbreeScene, PreGatheredSoupAndEmptyMeshWork) {
  const EmbreeDevice device;
  const TestMesh indexed = testing::make_random_soup(48, 800);
  std::vector<vec3> gathered;
  for (uint32_t index : indexed.indices) gathered.push_back(indexed.positions[index]);
  const EmbreeScene soup(device, make_triangle_soup(gathered), EmbreeQuality::low);
  const std::vector<Ray> rays = testing::make_random_rays(indexed, 49, 3000);
  std::vector<Hit> hits(rays.size());
  soup.trace_closest(rays, hits);
  for (size_t i = 0; i < rays.size(); ++i)
    ASSERT_TRUE(agrees(testing::brute_force_closest(indexed.view(), rays[i]), hits[i])) << "ray " << i;

  const TestMesh nothing;
  const EmbreeScene empty(device, nothing.view(), EmbreeQuality::medium);
  Hit hit;
  const Ray ray;
  empty.trace_closest(std::span(&ray, 1), std::span(&hit, 1));
  EXPECT_FALSE(hit.valid());
  EXPECT_TRUE(empty.bounds().empty());
}

TEST(EmbreeScene, BadInputIsAClearError) {
  const EmbreeDevice device;
  const TestMesh soup = testing::make_random_soup(50, 100);
  EmbreeScene scene(device, soup.view(), EmbreeQuality::refit);
  EXPECT_NE(glint::testing::error_of([&] { scene.update_vertices(std::span(soup.positions).first(3)); })
                .find("update with 3 vertices"),
            std::string::npos);
  std::vector<Ray> rays(4);
  std::vector<Hit> hits(3);
  EXPECT_THROW(scene.trace_closest(rays, hits), Error);
  EXPECT_NE(glint::testing::error_of([] { parse_embree_quality("ultra"); }).find("low, medium, high, refit"),
            std::string::npos);
  EXPECT_EQ(parse_embree_quality("refit"), EmbreeQuality::refit);
}

TEST(EmbreeDevice, EmbreeErrorsBecomeGlintErrorsWithEmbreesMessage) {
  const EmbreeDevice device;
  // A float index buffer is invalid; Embree reports it through the device's error callback.
  RTCGeometry geometry = rtcNewGeometry(device.handle(), RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_FLOAT, sizeof(float), 3);
  rtcReleaseGeometry(geometry);
  const std::string message = glint::testing::error_of([&] { device.check("test"); });
  EXPECT_NE(message.find("embree: test: RTC_ERROR_"), std::string::npos) << message;
  EXPECT_NO_THROW(device.check("after the error was reported"));
}

}  // namespace
}  // namespace glint::accel
