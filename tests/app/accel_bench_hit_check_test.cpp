// accel-bench's hit check on whole runs: scenes far from the origin and a camera inside a plane,
// where t is known only to float precision (what the interiors and the moved Sponza tripped
// over), and a real disagreement: counted, reported, fatal only under --strict-hits.
#include "accel/test_scenes.h"
#include "app/accel_bench/bench_run.h"
#include "app/accel_bench/hit_check.h"
#include "app/accel_bench/report_json.h"
#include "app/accel_bench/report_table.h"
#include "app/accel_bench_command.h"
#include "core/error.h"
#include "core/log.h"
#include "rt/tiny_scene.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include <cfloat>
#include <cmath>

namespace glint::accel_bench {
namespace {

using accel::testing::TestMesh;

// Triangle 0 and 1: two halves of the square [-10, 10]^2 in the plane z = -1 (normal +z); triangle
// 2 a copy of 0 (a duplicate, for ties).
TestMesh square_at_z_minus_1() {
  TestMesh mesh;
  mesh.add_triangle(vec3(-10, -10, -1), vec3(10, -10, -1), vec3(10, 10, -1));
  mesh.add_triangle(vec3(-10, -10, -1), vec3(10, 10, -1), vec3(-10, 10, -1));
  mesh.add_triangle(vec3(-10, -10, -1), vec3(10, -10, -1), vec3(10, 10, -1));
  return mesh;
}

accel::Ray ray_of(vec3 origin, vec3 direction) { return {origin, 0.0f, direction, accel::kInfinity}; }

// Two t of one point agree within a few float ulps of the largest coordinate around, divided by
// the incidence cosine, whatever t is; another triangle at such a t is a tie; anything farther is a
// disagreement.
TEST(AccelBenchHitRule, AcceptsTiesAndRejectsRealDifferences) {
  const TestMesh square = square_at_z_minus_1();
  const HitGeometry geometry = hit_geometry(square.view());
  EXPECT_EQ(geometry.magnitude, 10.0f);
  const accel::Ray ray = ray_of(vec3(1, 2, 3), vec3(0, 0, -1));  // head on: t = 4
  const accel::Hit miss;
  const accel::Hit a{4.0f, 0, 0, 0.1f, 0.2f};
  accel::Hit tie = a;
  tie.prim = 2;
  tie.t = 4.0f + 1e-4f;
  accel::Hit far = a;
  far.t = 4.001f;
  EXPECT_FALSE(hit_disagreement(ray, a, a, geometry));
  EXPECT_FALSE(hit_disagreement(ray, miss, miss, geometry));
  EXPECT_FALSE(hit_disagreement(ray, a, tie, geometry));
  EXPECT_TRUE(hit_disagreement(ray, a, far, geometry));
  EXPECT_TRUE(hit_disagreement(ray, a, miss, geometry));
  EXPECT_TRUE(hit_disagreement(ray, miss, a, geometry));
  accel::Hit unknown = a;
  unknown.prim = 3;
  EXPECT_TRUE(hit_disagreement(ray, a, unknown, geometry)) << "a triangle the scene does not have";

  // t is in units of the direction: a longer direction makes the same distance a smaller t.
  const float head_on = hit_t_tolerance(ray, geometry.magnitude, 1.0f);
  EXPECT_NEAR(head_on, kHitToleranceUlps * FLT_EPSILON * 10.0f, 1e-9f);
  EXPECT_FLOAT_EQ(hit_t_tolerance(ray_of(ray.origin, 4.0f * ray.direction), geometry.magnitude, 1.0f), 0.25f * head_on);
  // It follows the largest coordinate around, the scene's or the origin's.
  EXPECT_FLOAT_EQ(hit_t_tolerance(ray_of(vec3(0, -400, 0), ray.direction), geometry.magnitude, 1.0f), 40.0f * head_on);
  // And the incidence: at 60 degrees from the normal the plane's uncertainty is twice as long a t.
  const accel::Ray oblique = ray_of(vec3(1, 2, 3), vec3(std::sqrt(3.0f), 0, -1));
  EXPECT_NEAR(incidence_cosine(oblique, square.view().triangle(0)), 0.5f, 1e-6f);
  EXPECT_FLOAT_EQ(hit_t_tolerance(ray, geometry.magnitude, 0.5f), 2.0f * head_on);
  EXPECT_FLOAT_EQ(hit_t_tolerance(ray, geometry.magnitude, 0.0f), 1.0f / kMinIncidenceCosine * head_on);
  EXPECT_EQ(incidence_cosine(ray, accel::Triangle{vec3(0), vec3(1, 0, 0), vec3(2, 0, 0)}), 0.0f) << "degenerate";
}

// The numbers: an interior with coordinates up to 1,700 whose ray hits the same triangle at
// t 6.7479205 and 6.748987 (the old rule, 1e-4 relative to t, said no), and a camera inside a plane
// that sees it at t 0 or 1.4e-7 (its floor, 1e-7 absolute, said no). Both are float rounding; a
// hit 1 % farther is not, and neither is the same difference in a small scene.
TEST(AccelBenchHitRule, ScalesWithTheScenesCoordinatesNotWithT) {
  TestMesh interior;
  interior.add_triangle(vec3(700, 0, -1314), vec3(900, 0, -1314), vec3(800, 300, -1314));  // a wall, normal +z
  interior.add_triangle(vec3(-1700, 0, 0), vec3(-1600, 0, 0), vec3(-1650, 100, 0));      // far away
  const HitGeometry geometry = hit_geometry(interior.view());
  EXPECT_EQ(geometry.magnitude, 1700.0f);
  const accel::Ray ray = ray_of(vec3(812.0f, 96.5f, -1320.3f), glm::normalize(vec3(0.3f, -0.2f, 0.9f)));
  const accel::Hit embree{6.7479205f, 0, 0, 0.4f, 0.3f};
  accel::Hit sah = embree;
  sah.t = 6.748987f;
  EXPECT_FALSE(hit_disagreement(ray, sah, embree, geometry));
  accel::Hit farther = sah;
  farther.t = 6.82f;
  EXPECT_TRUE(hit_disagreement(ray, sah, farther, geometry));

  TestMesh small;
  small.add_triangle(vec3(-2, -2, -1), vec3(2, -2, -1), vec3(0, 2, -1));
  EXPECT_TRUE(hit_disagreement(ray_of(vec3(0.5f, 0.2f, -1.5f), ray.direction), sah, embree,
                               hit_geometry(small.view())));

  const TestMesh square = square_at_z_minus_1();
  const accel::Ray in_plane = ray_of(vec3(4.0f, 2.5f, -1.0f), glm::normalize(vec3(0.1f, 1.0f, -0.01f)));
  const accel::Hit at_origin{0.0f, 0, 1, 0.5f, 0.25f};
  accel::Hit just_after = at_origin;
  just_after.t = 1.4e-7f;
  EXPECT_FALSE(hit_disagreement(in_plane, at_origin, just_after, hit_geometry(square.view())));
  // ... or at t = -1e-7 in another structure: a miss, or the next hit behind.
  const accel::Hit miss;
  accel::Hit behind = at_origin;
  behind.prim = 0;
  behind.t = 5.0f;
  EXPECT_FALSE(hit_disagreement(in_plane, at_origin, miss, hit_geometry(square.view())));
  EXPECT_FALSE(hit_disagreement(in_plane, miss, just_after, hit_geometry(square.view())));
  EXPECT_FALSE(hit_disagreement(in_plane, behind, just_after, hit_geometry(square.view())));
  accel::Hit clear_of_origin = at_origin;
  clear_of_origin.t = 0.1f;
  EXPECT_TRUE(hit_disagreement(in_plane, clear_of_origin, miss, hit_geometry(square.view())));
  EXPECT_TRUE(hit_disagreement(in_plane, behind, clear_of_origin, hit_geometry(square.view())));
}

// A structure that misses a hit lying on its triangle's edge (within single precision) is counted
// apart, up to a budget; any other disagreement is counted as one, the first described.
TEST(AccelBenchHitRule, EdgeGrazesAreCountedApartWithinABudget) {
  const TestMesh square = square_at_z_minus_1();
  const HitGeometry geometry = hit_geometry(square.view());
  const accel::Hit miss;
  const accel::Hit on_edge{14.2f, 0, 0, 0.67f, 2e-6f};
  const accel::Hit inside{14.2f, 0, 1, 0.3f, 0.3f};
  accel::Hit beyond = inside;
  beyond.t = 16.8f;
  beyond.prim = 2;
  EXPECT_TRUE(is_edge_graze(on_edge, beyond)) << "the reference's nearer hit grazes an edge, the other went past";
  EXPECT_TRUE(is_edge_graze(on_edge, miss));
  EXPECT_TRUE(is_edge_graze(miss, on_edge));
  EXPECT_FALSE(is_edge_graze(inside, beyond)) << "a hit well inside its triangle must not be missed";

  std::vector<accel::Ray> rays(20000, ray_of(vec3(0, 0, 13.2f), vec3(0, 0, -1)));
  std::vector<accel::Hit> reference(rays.size(), inside), hits(rays.size(), inside);
  reference[10] = on_edge;
  hits[10] = beyond;
  const HitCheck one = check_hits("embree-low", "sah", rays, reference, hits, geometry);
  EXPECT_EQ(one.edge_grazes, 1u);
  EXPECT_EQ(one.disagreements, 0u);
  EXPECT_TRUE(one.agrees()) << one.problem;
  reference[11] = on_edge;
  hits[11] = miss;
  reference[12] = on_edge;
  hits[12] = miss;
  const HitCheck too_many = check_hits("embree-low", "sah", rays, reference, hits, geometry);
  EXPECT_EQ(too_many.edge_grazes, 3u);
  EXPECT_FALSE(too_many.agrees());
  EXPECT_NE(too_many.problem.find("3 of 20000 rays"), std::string::npos) << too_many.problem;
  hits[11] = reference[11];
  hits[12] = reference[12];
  hits[13] = beyond;
  hits[17] = miss;
  const HitCheck real = check_hits("embree-low", "sah", rays, reference, hits, geometry);
  EXPECT_EQ(real.disagreements, 2u);
  EXPECT_EQ(real.edge_grazes, 1u);
  EXPECT_NE(real.problem.find("embree-low disagrees with sah on 2 of 20000 rays; first: ray 13 "), std::string::npos)
      << real.problem;
  EXPECT_THROW((void)check_hits("embree-low", "sah", rays, reference, std::span(hits).first(5), geometry), Error);
}

// `scene` scaled by `scale` about the world origin, then moved by `offset`: instances, camera path,
// light path and light, so the walkthrough sees the same picture.
void scale_and_move(Scene& scene, float scale, vec3 offset) {
  const mat4 to_world = glm::scale(glm::translate(mat4(1.0f), offset), vec3(scale));
  for (Instance& instance : scene.instances) instance.transform = to_world * instance.transform;
  const auto move = [&](vec3& p) { p = vec3(to_world * vec4(p, 1.0f)); };
  for (vec3& p : scene.walkthrough.camera.points) move(p);
  for (vec3& p : scene.walkthrough.camera.targets) move(p);
  for (vec3& p : scene.walkthrough.light.points) move(p);
  move(scene.light.position);
  scene.validate();
}

BenchOptions cpu_options(RayKind rays) {
  BenchOptions options;
  options.structures = parse_structure_list("all");  // every CPU structure and Embree
  options.rays = rays;
  options.frames = {0, 50, 99};
  options.width = 48;
  options.height = 32;
  options.deform_frames = 3;
  options.timed_runs = 1;
  options.build_runs = 1;
  return options;
}

void expect_every_check_passed(const BenchReport& report) {
  for (const StructureResult& r : report.structures) {
    EXPECT_TRUE(r.mrays_per_s.has_value()) << r.name << " " << r.skipped;
    EXPECT_EQ(r.disagreements, 0u) << r.hit_problem;
  }
  for (const DeformResult& d : report.deform) EXPECT_EQ(d.disagreements.value_or(0), 0u) << d.hit_problem;
  EXPECT_TRUE(hit_problems(report).empty());
}

// The tiny scene scaled by 1000 and moved to (20000, 5000, -30000): coordinates up to 38,000, where a
// float's ulp is 0.004. With the old rule (1e-4 of t) Embree disagreed on 2 of the 4,608 random rays
// (which start anywhere in the box, so t can be short): the same triangle at t 3.78364 and 3.78287.
class AccelBenchFarFromOrigin : public ::testing::TestWithParam<RayKind> {};

TEST_P(AccelBenchFarFromOrigin, EveryCpuStructureAgreesWithTheReference) {
  Scene scene = glint::testing::make_tiny_scene(16);
  scale_and_move(scene, 1000.0f, vec3(20000.0f, 5000.0f, -30000.0f));
  const BenchReport report = run_accel_bench(scene, cpu_options(GetParam()));
  EXPECT_EQ(report.reference, "none");
  EXPECT_GT(report.ray_hits, 0u);
  expect_every_check_passed(report);
}

INSTANTIATE_TEST_SUITE_P(AccelBench, AccelBenchFarFromOrigin,
                         ::testing::Values(RayKind::primary, RayKind::reflection, RayKind::random),
                         [](const ::testing::TestParamInfo<RayKind>& param) { return std::string(ray_kind_name(param.param)); });

// A lone square plane seen by a camera inside it, so that every primary ray that goes down hits it
// at t = 0 give or take float rounding (t 0 in one structure, 1.4e-7 in another, or just below 0,
// i.e. a miss): the plane-only OBJ, whose default walkthrough then put the camera at a
// third of the plane's zero height. Axis-aligned, or tilted and moved away, the camera then on the
// plane only to float rounding.
Scene plane_scene(float half, const mat4& placement) {
  Scene scene;
  scene.name = "plane";
  scene.materials.emplace_back();
  Mesh mesh;
  mesh.name = "plane";
  mesh.positions = {vec3(-half, 0, half), vec3(half, 0, half), vec3(half, 0, -half), vec3(-half, 0, -half)};
  mesh.normals.assign(4, vec3(0, 1, 0));
  mesh.indices = {0, 1, 2, 0, 2, 3};
  scene.meshes.push_back(mesh);
  scene.instances.push_back({"plane", 0, placement});
  const auto on_plane = [&](float x, float z) { return vec3(placement * vec4(x * half, 0.0f, z * half, 1.0f)); };
  scene.walkthrough.camera.points = {on_plane(-0.6f, 0.5f), on_plane(0.1f, 0.3f), on_plane(0.5f, 0.45f)};
  scene.walkthrough.camera.targets = {on_plane(0.2f, -0.7f)};
  scene.walkthrough.light.points = {on_plane(0.0f, 0.0f) + vec3(0.0f, half, 0.0f)};
  scene.walkthrough.frame_count = 100;
  scene.validate();
  return scene;
}

TEST(AccelBenchPlane, PrimaryRaysFromInsideThePlaneAgree) {
  const mat4 tilted_far = glm::rotate(glm::rotate(glm::translate(mat4(1.0f), vec3(1234.5f, 678.9f, -2345.6f)),
                                                  glm::radians(20.0f), vec3(0, 1, 0)),
                                      glm::radians(30.0f), vec3(1, 0, 0));
  for (const mat4& placement : {mat4(1.0f), tilted_far})
    for (const float half : {1.0f, 10.0f, 1000.0f}) {
      Scene scene = plane_scene(half, placement);
      const BenchReport report = run_accel_bench(scene, cpu_options(RayKind::primary));
      EXPECT_GT(report.ray_hits, 0u) << half;
      SCOPED_TRACE(fmt::format("half size {}, {}", half, placement == mat4(1.0f) ? "axis-aligned" : "tilted"));
      expect_every_check_passed(report);
    }
}

// Another triangle at a clearly different t is a real disagreement: counted for that structure
// alone (table, JSON), the run goes on, and only --strict-hits turns it into a failing exit status.
TEST(AccelBenchDisagreement, IsCountedAndFatalOnlyWhenStrict) {
  Scene scene = glint::testing::make_tiny_scene(4);
  BenchOptions options = cpu_options(RayKind::primary);
  options.structures = {"sah", "trbvh-wide8", "embree-low", "embree-medium"};
  options.deform_frames = 0;
  size_t wrong_ray = 0;
  options.tamper_hits = [&](const std::string& name, std::span<accel::Hit> hits) {
    if (name != "trbvh-wide8") return;
    while (!hits[wrong_ray].valid()) ++wrong_ray;
    hits[wrong_ray].prim ^= 1u;     // the other half of its quad
    hits[wrong_ray].t *= 1.5f;
  };
  const BenchReport report = run_accel_bench(scene, options);
  ASSERT_EQ(report.structures.size(), 4u);
  for (const StructureResult& r : report.structures) {
    EXPECT_TRUE(r.mrays_per_s.has_value()) << r.name;
    EXPECT_EQ(r.disagreements, r.name == "trbvh-wide8" ? 1u : 0u) << r.name;
  }
  const std::vector<std::string> problems = hit_problems(report);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find(fmt::format("trbvh-wide8 disagrees with sah on 1 of {} rays; first: ray {} ",
                                         report.ray_count, wrong_ray)),
            std::string::npos)
      << problems[0];

  const std::string table = format_report_table(report);
  EXPECT_NE(table.find("disagree"), std::string::npos) << table;
  const size_t row = table.find("trbvh-wide8");
  ASSERT_NE(row, std::string::npos);
  const std::string line = table.substr(row, table.find('\n', row) - row);
  EXPECT_TRUE(line.ends_with(" 1")) << line;  // the last column, disagree
  const nlohmann::json j = report_json(report, current_machine(1));
  EXPECT_EQ(j["structures"][1]["disagreements"], 1);
  EXPECT_EQ(j["structures"][1]["disagreement"], problems[0]);
  EXPECT_EQ(j["structures"][2]["disagreements"], 0);

  {
    const ScopedLogCapture log;
    EXPECT_EQ(hit_check_exit_code(report, false), 0);
    EXPECT_EQ(log.count_warnings("trbvh-wide8 disagrees with sah"), 1);
    EXPECT_EQ(log.count_warnings("--strict-hits makes this an error"), 1);
  }
  {
    const ScopedLogCapture log;
    EXPECT_EQ(hit_check_exit_code(report, true), kHitDisagreementExitCode);
    EXPECT_EQ(log.count_warnings(""), 0);
    ASSERT_EQ(log.entries().size(), 2u);
    EXPECT_EQ(log.entries()[0].level, LogLevel::error);
    EXPECT_EQ(log.entries()[0].message, "accel-bench: " + problems[0]);
  }
}

}  // namespace
}  // namespace glint::accel_bench
