// The gl backend's update_gl under every update policy (GlRayTracer, docs/ray-tracer.md "gl"), after
// positions written into its GL vertex buffer as a GL-side deformer writes them: the SAH cost measured
// in GL compute (GlSahCost) equals accel::compute_stats's over the same refitted nodes read back
// (also scaled by 1000 and far from the origin, and with other cost constants); automatic rebuilds a
// BLAS within a few updates once its measured cost passed the ratio, and the structures then trace as
// the cpu backend built from the same posed positions; with a huge ratio it only refits; rebuild
// rebuilds every dirty mesh on the host from the positions read back, node for node as a host build.
#include "gl_rt/gl_ray_tracer.h"

#include "accel/bvh_stats.h"
#include "accel/tlas.h"
#include "backends/registry.h"
#include "gl/gl_test_context.h"
#include "gl/read_buffer.h"
#include "gl_rt/gl_sah_cost.h"
#include "gl_rt/mesh_blases.h"
#include "gl_rt/write_gl_positions.h"
#include "rt/ray_tracer_check.h"
#include "scene/sine_deformer.h"

#include <gtest/gtest.h>

#include <numeric>
#include <string>
#include <vector>

namespace glint::gl_rt {
namespace {

using rt::UpdatePolicy;
using testing::brute_force_hits;
using testing::compare_hits;
using testing::random_rays;
using testing::read_buffer;
using testing::trace;
using testing::write_gl_positions;

using GlGpuUpdatePolicies = testing::GlTest;

// Every mesh's object-space positions scaled and moved (the deformation with them), so the BLASes'
// own boxes are large and far from the origin, where their areas round most.
Scene placed(Scene scene, float scale, vec3 offset) {
  for (Mesh& mesh : scene.meshes) {
    for (vec3& p : mesh.positions) p = p * scale + offset;
    if (mesh.deform) {
      mesh.deform->amplitude *= scale;
      mesh.deform->frequency /= scale;
    }
  }
  return scene;
}

// Posed at `frame`, written into the tracer's positions, updated by `policy`; returns the dirty meshes.
std::vector<uint32_t> pose_and_update(GlRayTracer& tracer, Scene& scene, SceneDeformers& deformers, int frame,
                                      UpdatePolicy policy) {
  const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
  EXPECT_FALSE(dirty.empty());
  write_gl_positions(*tracer.gl_tracing(), scene, dirty);
  tracer.update_gl(dirty, policy);
  return dirty;
}

// Boxes equal as floats (min and max do not round; a build is deterministic), topology bit for bit.
bool same_node(const accel::BvhNode& a, const accel::BvhNode& b) {
  return a.bounds_min == b.bounds_min && a.bounds_max == b.bounds_max && a.first == b.first &&
         a.prim_count == b.prim_count;
}

// The BVH of mesh `m` as the GL node array holds it.
accel::Bvh gl_bvh(const GlRayTracer& tracer, uint32_t m) {
  const GlStructureBuffers::BlasRegion& region = tracer.structures().region(m);
  accel::Bvh bvh;
  const std::vector<accel::BvhNode> nodes =
      read_buffer<accel::BvhNode>(tracer.structures().nodes(), region.node_offset, region.node_count);
  bvh.nodes.assign(nodes.begin(), nodes.end());
  return bvh;
}

// At three poses refitted on the GPU: every BLAS's GPU cost against the host's over its nodes read
// back, and stats()'s drift against the host's drift over those costs.
void expect_gpu_sah_equals_host(Scene scene, const rt::AccelOptions& options, const std::string& what) {
  GlRayTracer tracer;
  tracer.build(scene, options);
  MeshBlases built;
  built.build(scene, options);
  SceneDeformers deformers(scene);
  GlSahCost sah;
  const accel::SahCosts costs = accel::sah_costs(options.build);
  std::vector<uint32_t> all(scene.meshes.size());
  std::iota(all.begin(), all.end(), 0u);
  for (int frame : {9, 37, 70}) {
    (void)pose_and_update(tracer, scene, deformers, frame, UpdatePolicy::refit);
    const std::vector<double> gpu = sah.measure_now(tracer.structures(), all, costs);
    double drift = 0.0;
    for (uint32_t m : all) {
      const double host = accel::compute_stats(gl_bvh(tracer, m), costs).sah_cost;
      ASSERT_GT(host, 0.0) << what;
      // The same float areas, summed in double in another order.
      EXPECT_NEAR(gpu[m], host, 1e-9 * host) << what << " frame " << frame << " mesh " << m;
      if (scene.meshes[m].deformable) drift = std::max(drift, host / built.meshes()[m].sah_at_rebuild);
    }
    ASSERT_NE(drift, 1.0) << what << ": the deformation must change the cost";
    const std::optional<double> reported = tracer.stats().blas_sah_drift;
    ASSERT_TRUE(reported.has_value()) << what;
    EXPECT_NEAR(*reported, drift, 1e-9 * drift) << what << " frame " << frame;
  }
}

TEST_F(GlGpuUpdatePolicies, GpuSahCostEqualsTheHostsOverTheSameNodes) {
  expect_gpu_sah_equals_host(testing::make_strongly_deforming_scene(), {}, "instanced");
  rt::AccelOptions other_costs;
  other_costs.builder = accel::BvhBuilder::lbvh;
  other_costs.build.traversal_cost = 2.5f;
  other_costs.build.intersection_cost = 0.75f;
  expect_gpu_sah_equals_host(testing::make_strongly_deforming_scene(), other_costs, "lbvh, costs 2.5 and 0.75");
  expect_gpu_sah_equals_host(placed(testing::make_strongly_deforming_scene(), 1000.0f, vec3(1.0e4f, -1.0e4f, 1.0e4f)), {},
                             "x1000, 1e4 from the origin");
  expect_gpu_sah_equals_host(testing::make_reduced_atrium(), {}, "reduced atrium");
}

// Closest hits of `rays` against the cpu backend built from the scene as posed now, and brute force.
void expect_traces_as_a_host_build(const GlRayTracer& tracer, const Scene& scene, const rt::AccelOptions& options,
                                   const std::vector<accel::Ray>& rays, const std::string& what) {
  const auto cpu = backends::make_ray_tracer("cpu");
  cpu->build(scene, options);
  const std::vector<accel::Hit> hits = trace(tracer, rays);
  EXPECT_EQ(compare_hits(scene, rays, trace(*cpu, rays), hits), "") << what;
  EXPECT_EQ(compare_hits(scene, rays, brute_force_hits(scene, rays), hits), "") << what;
}

// The strongly deforming scene and a gl tracer built over it with `ratio` as its
// auto_rebuild_sah_ratio, updated by the automatic policy.
struct AutomaticRun {
  Scene scene = testing::make_strongly_deforming_scene();
  rt::AccelOptions options;
  GlRayTracer tracer;
  SceneDeformers deformers{scene};

  explicit AutomaticRun(float ratio) {
    options.auto_rebuild_sah_ratio = ratio;
    tracer.build(scene, options);
  }
  // Posed at `frame` and updated; then the test waits for the GPU, so that this update's measurement
  // is ready for the next one (a frame never waits for it). Returns the dirty meshes' count.
  size_t update(int frame) {
    const size_t dirty = pose_and_update(tracer, scene, deformers, frame, UpdatePolicy::automatic).size();
    glFinish();
    return dirty;
  }
};

TEST_F(GlGpuUpdatePolicies, AutomaticRebuildsOnceTheMeasuredCostPassedTheRatio) {
  AutomaticRun run(1.0001f);
  const Scene& scene = run.scene;
  const std::vector<accel::Ray> rays = random_rays(scene, 1000, 17);
  const std::vector<accel::Hit> rest = brute_force_hits(scene, rays);
  int updates = 0;
  for (int frame = 13; run.tracer.stats().rebuilds == 0 && updates < 6; frame += 11, ++updates) (void)run.update(frame);
  const rt::RayTracerStats stats = run.tracer.stats();
  ASSERT_GT(stats.rebuilds, 0u) << "no rebuild in " << updates << " updates";
  // The first update has no measurement yet: it refits.
  EXPECT_GE(updates, 2);
  EXPECT_GT(stats.refits, 0u);
  ASSERT_NE(compare_hits(scene, rays, rest, brute_force_hits(scene, rays)), "") << "the pose must change some hits";
  expect_traces_as_a_host_build(run.tracer, scene, run.options, rays, "after the rebuild");
  // The rebuilt BLAS is the host build over the posed positions, node for node: the sheet's.
  MeshBlases host;
  host.build(scene, run.options);
  const auto& expected = host.meshes()[2].bvh.nodes;
  const accel::Bvh gl = gl_bvh(run.tracer, 2);
  ASSERT_EQ(gl.nodes.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) ASSERT_TRUE(same_node(gl.nodes[i], expected[i])) << "node " << i;
  // Refits on the GPU go on from the new BVH.
  for (int frame : {80, 91}) {
    (void)run.update(frame);
    expect_traces_as_a_host_build(run.tracer, scene, run.options, rays, "frame " + std::to_string(frame));
  }
}

TEST_F(GlGpuUpdatePolicies, AutomaticWithAHugeRatioOnlyRefits) {
  AutomaticRun run(1.0e30f);
  const std::vector<accel::Ray> rays = random_rays(run.scene, 600, 5);
  size_t dirty = 0;
  for (int frame = 13; frame < 13 + 6 * 11; frame += 11) dirty += run.update(frame);
  const rt::RayTracerStats stats = run.tracer.stats();
  EXPECT_EQ(stats.rebuilds, 0u);
  EXPECT_EQ(stats.refits, dirty);
  ASSERT_TRUE(stats.blas_sah_drift.has_value());
  EXPECT_GT(*stats.blas_sah_drift, 1.0001) << "the same deformation that rebuilds at a ratio of 1.0001";
  expect_traces_as_a_host_build(run.tracer, run.scene, run.options, rays, "refitted only");
}

// Every update rebuilds every dirty mesh from the positions read back and builds the TLAS anew: the
// structures are, node for node, the host's build over the posed scene (sbvh too, whose BVHs may
// outgrow their regions and lay the buffers out again).
TEST_F(GlGpuUpdatePolicies, RebuildBuildsOnTheHostFromThePositionsReadBack) {
  for (accel::BvhBuilder builder : {accel::BvhBuilder::sah, accel::BvhBuilder::sbvh}) {
    const std::string what(accel::builder_name(builder));
    Scene scene = testing::make_strongly_deforming_scene();
    const std::vector<accel::Ray> rays = random_rays(scene, 600, 8);
    rt::AccelOptions options;
    options.builder = builder;
    GlRayTracer tracer;
    tracer.build(scene, options);
    SceneDeformers deformers(scene);
    size_t dirty = 0;
    for (int frame : {17, 40}) {
      dirty += pose_and_update(tracer, scene, deformers, frame, UpdatePolicy::rebuild).size();
      const std::string pose = what + " frame " + std::to_string(frame);
      expect_traces_as_a_host_build(tracer, scene, options, rays, pose);
      MeshBlases host;
      host.build(scene, options);
      for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
        const auto& expected = host.meshes()[m].bvh.nodes;
        const accel::Bvh gl = gl_bvh(tracer, m);
        ASSERT_EQ(gl.nodes.size(), expected.size()) << pose << " mesh " << m;
        for (size_t i = 0; i < expected.size(); ++i)
          ASSERT_TRUE(same_node(gl.nodes[i], expected[i])) << pose << " mesh " << m << " node " << i;
      }
      std::vector<accel::Instance> instances;
      for (const Instance& instance : scene.instances)
        instances.push_back(accel::make_instance(instance.mesh, instance.transform));
      const accel::Tlas tlas =
          accel::build_tlas(host.blases(), std::move(instances), accel::BvhBuilder::sah, options.build);
      ASSERT_EQ(tracer.structures().tlas_node_count(), tlas.bvh.nodes.size()) << pose << ": the TLAS built anew";
      const std::vector<accel::BvhNode> gl_tlas =
          read_buffer<accel::BvhNode>(tracer.structures().nodes(), 0, tlas.bvh.nodes.size());
      for (size_t i = 0; i < gl_tlas.size(); ++i)
        ASSERT_TRUE(same_node(gl_tlas[i], tlas.bvh.nodes[i])) << pose << " TLAS node " << i;
    }
    const rt::RayTracerStats stats = tracer.stats();
    EXPECT_EQ(stats.rebuilds, dirty) << what;
    EXPECT_EQ(stats.refits, 0u) << what;
    EXPECT_EQ(stats.blas_sah_drift, 1.0) << what;
  }
}

}  // namespace
}  // namespace glint::gl_rt
