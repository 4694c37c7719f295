// accel-bench's hit check on whole runs: scenes far from the origin and a camera inside a plane,
// where t is known only to float precision (what the interiors and the moved Sponza tripped
// over), and a real disagreement: counted, reported, fatal only under --strict-hits.
#include "app/accel_bench/bench_run.h"
#include "app/accel_bench/report_json.h"
#include "app/accel_bench/report_table.h"
#include "app/accel_bench_command.h"
#include "core/log.h"
#include "rt/tiny_scene.h"
#include "scene/default_walkthrough.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace glint::accel_bench {
namespace {

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
    EXPECT_EQ(r.edge_grazes, 0u) << r.name;
  }
  for (const DeformResult& d : report.deform) EXPECT_EQ(d.disagreements.value_or(0), 0u) << d.hit_problem;
  EXPECT_TRUE(hit_problems(report).empty());
}

class AccelBenchFarFromOrigin : public ::testing::TestWithParam<RayKind> {};

TEST_P(AccelBenchFarFromOrigin, EveryCpuStructureAgreesWithTheReference) {
  Scene scene = glint::testing::make_tiny_scene(16);
  scale_and_move(scene, 1000.0f, vec3(20000.0f, 5000.0f, -30000.0f));
  const BenchReport report = run_accel_bench(scene, cpu_options(GetParam()));
  EXPECT_EQ(report.reference, "none");
  EXPECT_GT(report.ray_hits, 0u);
  expect_every_check_passed(report);
}

INSTANTIATE_TEST_SUITE_P(RayKinds, AccelBenchFarFromOrigin,
                         ::testing::Values(RayKind::primary, RayKind::reflection, RayKind::random),
                         [](const ::testing::TestParamInfo<RayKind>& param) { return std::string(ray_kind_name(param.param)); });

// A lone plane: the default walkthrough puts the camera in the plane (at a third of its zero
// height), so the primary rays that go down hit it at t = 0 give or take float rounding.
TEST(AccelBenchPlane, PrimaryRaysFromInsideThePlaneAgree) {
  for (const float half : {1.0f, 10.0f, 1000.0f}) {
    Scene scene;
    scene.name = "plane";
    scene.materials.emplace_back();
    Mesh mesh;
    mesh.name = "plane";
    mesh.positions = {vec3(-half, 0, half), vec3(half, 0, half), vec3(half, 0, -half), vec3(-half, 0, -half)};
    mesh.normals.assign(4, vec3(0, 1, 0));
    mesh.indices = {0, 1, 2, 0, 2, 3};
    scene.meshes.push_back(mesh);
    scene.instances.push_back({"plane", 0, mat4(1.0f)});
    scene.walkthrough.frame_count = 100;
    assign_default_walkthrough(scene);
    scene.validate();
    const BenchReport report = run_accel_bench(scene, cpu_options(RayKind::primary));
    EXPECT_GT(report.ray_hits, 0u) << half;
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
