// The gl backend's GPU refit (GlRayTracer::update_gl, gl_rt/gl_refit.h): positions written into the
// tracer's GL vertex buffer (GlTracing::gl_positions) and refitted in GL compute give every BLAS node
// the box accel::refit gives on the CPU, exactly, and leave every arrival counter at 0; the TLAS keeps
// its topology and takes the boxes accel::refit_tlas gives (each instance's world box by accel's
// rule); closest hits and occlusion equal the cpu backend's, refitted on the host (brute force on the
// plain scenes too), also scaled by 1000 and far from the origin, and with thousands of instances; a
// host update after GPU refits is correct.
#include "gl_rt/gl_ray_tracer.h"

#include "accel/refit.h"
#include "backends/registry.h"
#include "accel/tlas.h"
#include "gl/gl_test_context.h"
#include "gl/read_buffer.h"
#include "gl_rt/write_gl_positions.h"
#include "gl_rt/mesh_blases.h"
#include "render/transformed_scene.h"
#include "rt/ray_tracer_check.h"
#include "scene/sine_deformer.h"
#include "support/error_of.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <string>
#include <tuple>
#include <vector>

namespace glint::gl_rt {
namespace {

using rt::UpdatePolicy;
using testing::brute_force_hits;
using testing::brute_force_occluded;
using testing::compare_hits;
using testing::compare_occluded;
using testing::random_rays;
using testing::trace;
using testing::read_buffer;
using testing::trace_occluded;
using testing::write_gl_positions;

using GlRefitTest = testing::GlTest;


// Boxes equal as floats (min and max do not round), topology equal bit for bit. "" when all equal.
std::string compare_nodes(std::span<const accel::BvhNode> expected, std::span<const accel::BvhNode> gl,
                          const std::string& what) {
  size_t wrong = 0;
  std::string first;
  for (size_t i = 0; i < expected.size(); ++i) {
    const accel::BvhNode &e = expected[i], &g = gl[i];
    if (e.bounds_min == g.bounds_min && e.bounds_max == g.bounds_max && e.first == g.first &&
        e.prim_count == g.prim_count)
      continue;
    if (wrong++ == 0) first = " (first: node " + std::to_string(i) + ")";
  }
  return wrong == 0 ? "" : what + ": " + std::to_string(wrong) + " of " + std::to_string(expected.size()) +
                               " nodes differ" + first;
}

// The host's twin of a tracer's structures: the same builders over the same scene give the same BVHs.
struct HostStructures {
  MeshBlases blases;
  accel::Tlas tlas;

  HostStructures(const Scene& scene, const rt::AccelOptions& options) {
    blases.build(scene, options);
    std::vector<accel::Instance> instances;
    for (const Instance& instance : scene.instances) instances.push_back(accel::make_instance(instance.mesh, instance.transform));
    tlas = accel::build_tlas(blases.blases(), std::move(instances), accel::BvhBuilder::sah, options.build);
  }
};

// Every BLAS node, the TLAS nodes and the counters of `tracer` against `host`.
void expect_structures_equal(const GlRayTracer& tracer, const HostStructures& host, const std::string& what) {
  const GlStructureBuffers& gl = tracer.structures();
  for (uint32_t m = 0; m < host.blases.meshes().size(); ++m) {
    const auto& nodes = host.blases.meshes()[m].bvh.nodes;
    ASSERT_EQ(gl.region(m).node_count, nodes.size());
    EXPECT_EQ(compare_nodes(nodes, read_buffer<accel::BvhNode>(gl.nodes(), gl.region(m).node_offset, nodes.size()),
                            what + ", BLAS " + std::to_string(m)),
              "");
  }
  const auto& tlas = host.tlas.bvh.nodes;
  ASSERT_EQ(gl.tlas_node_count(), tlas.size());
  EXPECT_EQ(compare_nodes(tlas, read_buffer<accel::BvhNode>(gl.nodes(), 0, tlas.size()), what + ", TLAS"), "");
  // Each TLAS leaf holds its instances' world boxes (accel's rule) and equals their union.
  const std::vector<Aabb> world = accel::instance_world_boxes(host.blases.blases(), host.tlas.instances);
  const std::vector<accel::BvhNode> gl_tlas = read_buffer<accel::BvhNode>(gl.nodes(), 0, tlas.size());
  size_t outside = 0;
  for (const accel::BvhNode& node : gl_tlas) {
    if (!node.is_leaf()) continue;
    for (uint32_t slot = node.first; slot != node.first + node.prim_count; ++slot) {
      const Aabb& box = world[host.tlas.bvh.prim_indices[slot]];
      if (box.empty()) continue;
      outside += glm::any(glm::lessThan(box.min, node.bounds_min)) || glm::any(glm::greaterThan(box.max, node.bounds_max));
    }
  }
  EXPECT_EQ(outside, 0u) << what << ": instances' world boxes outside their TLAS leaf";
  // The second arrival at a node resets its counter: after a refit every counter is 0.
  const size_t links = gl.region(static_cast<uint32_t>(gl.mesh_count() - 1)).node_offset +
                       gl.region(static_cast<uint32_t>(gl.mesh_count() - 1)).node_capacity;
  size_t counting = 0;
  for (const glm::uvec2& link : read_buffer<glm::uvec2>(gl.links(), 0, links)) counting += link.y != 0 ? 1 : 0;
  EXPECT_EQ(counting, 0u) << what << ": arrival counters left non-zero";
}

// At three poses: the GL positions written, update_gl, the host refitted by accel's refit on the same
// positions; the structures equal, and hits and occlusion of `rays` (and of edge and vertex rays)
// equal the cpu backend's, updated on the host, and with `brute_force` brute force's too (whose
// world-space triangles round apart from the object-space walk's in a scaled or moved scene).
void check_gpu_refits(Scene scene, const rt::AccelOptions& options, const std::vector<accel::Ray>& rays,
                      const std::string& what, bool brute_force) {
  GlRayTracer tracer;
  tracer.build(scene, options);
  const auto cpu = backends::make_ray_tracer("cpu");
  cpu->build(scene, options);
  HostStructures host(scene, options);
  expect_structures_equal(tracer, host, what + " as built");
  SceneDeformers deformers(scene);
  const std::vector<accel::Hit> rest = trace(*cpu, rays);
  for (int frame : {17, 40, 63}) {
    const std::vector<uint32_t> dirty = deformers.apply(scene, frame);
    ASSERT_FALSE(dirty.empty());
    write_gl_positions(*tracer.gl_tracing(), scene, dirty);
    tracer.gl_tracing()->update_gl(dirty, UpdatePolicy::refit);
    (void)host.blases.update(scene, dirty, UpdatePolicy::refit);
    accel::refit_tlas(host.tlas, host.blases.blases());
    const std::string pose = what + " frame " + std::to_string(frame);
    expect_structures_equal(tracer, host, pose);

    cpu->update(scene, dirty, UpdatePolicy::refit);
    const std::vector<accel::Hit> expected = trace(*cpu, rays);
    ASSERT_NE(compare_hits(scene, rays, rest, expected), "") << pose << ": the deformation must change some hits";
    const std::vector<accel::Hit> hits = trace(tracer, rays);
    EXPECT_EQ(compare_hits(scene, rays, expected, hits), "") << pose;
    if (brute_force) {
      EXPECT_EQ(compare_hits(scene, rays, brute_force_hits(scene, rays), hits), "") << pose;
    }
    std::vector<accel::Ray> occlusion_rays = rays;
    const std::vector<accel::Ray> edges = testing::edge_and_vertex_rays(scene, 200, 3);
    occlusion_rays.insert(occlusion_rays.end(), edges.begin(), edges.end());
    const std::vector<uint8_t> occluded = trace_occluded(tracer, occlusion_rays);
    EXPECT_EQ(compare_occluded(occlusion_rays, trace_occluded(*cpu, occlusion_rays), occluded), "")
        << pose << " occlusion";
    if (brute_force) {
      EXPECT_EQ(compare_occluded(occlusion_rays, brute_force_occluded(scene, occlusion_rays), occluded), "")
          << pose << " occlusion";
    }
  }
  const rt::RayTracerStats stats = tracer.stats();
  EXPECT_EQ(stats.refits, 3 * deformers.meshes().size()) << what;
  EXPECT_EQ(stats.rebuilds, 0u) << what;
  // Measured on the GPU (the host's BVHs are older): the host's drift over the same refitted boxes.
  ASSERT_TRUE(stats.blas_sah_drift.has_value()) << what;
  const double host_drift = host.blases.sah_drift().value();
  EXPECT_NEAR(*stats.blas_sah_drift, host_drift, 1e-6 * host_drift) << what;
}

TEST_F(GlRefitTest, BoxesEqualTheHostRefitAndHitsEqualBruteForceOnTheInstancedScene) {
  for (accel::BvhBuilder builder : {accel::BvhBuilder::sah, accel::BvhBuilder::lbvh}) {
    rt::AccelOptions options;
    options.builder = builder;
    const Scene scene = testing::make_instanced_scene(16);
    check_gpu_refits(scene, options, random_rays(scene, 1000, 5), std::string(accel::builder_name(builder)), true);
  }
}

TEST_F(GlRefitTest, BoxesEqualTheHostRefitOnTheReducedAtriumScaledAndFarFromTheOrigin) {
  const Scene atrium = testing::make_reduced_atrium();
  check_gpu_refits(atrium, {}, random_rays(atrium, 200, 5), "reduced atrium", true);
  for (const auto& [scale, offset, what] : {std::tuple{1000.0f, vec3(0.0f), "x1000"},
                                            std::tuple{1.0f, vec3(1.0e5f, 0.0f, -3.0e4f), "far"}}) {
    const Scene scene = testing::transformed(atrium, scale, offset);
    check_gpu_refits(scene, {}, random_rays(scene, 200, 5), what, false);
  }
}

// Thousands of instances of the deforming sheet and the tetrahedron: the TLAS refit's climb over a
// deep TLAS, and one BLAS dispatch for both meshes.
TEST_F(GlRefitTest, ThousandsOfInstancesTakeTheHostsBoxes) {
  Scene scene = testing::make_instanced_scene(8);
  // Rays where the original instances stay, among the copies' boxes.
  const std::vector<accel::Ray> rays = random_rays(scene, 600, 5);
  const std::vector<Instance> originals = scene.instances;
  for (int i = 0; i < 3000; ++i) {
    Instance copy = originals[static_cast<size_t>(i) % originals.size()];
    copy.transform = glm::rotate(glm::translate(mat4(1.0f), vec3(float(i % 60) * 7.0f, float(i / 60) * 5.0f, -40.0f)),
                                 0.01f * float(i), vec3(0.3f, 1.0f, 0.2f)) *
                     copy.transform;
    scene.instances.push_back(copy);
  }
  check_gpu_refits(scene, {}, rays, "3,003 instances", false);
}

// A host update after GPU refits takes the GPU-refitted meshes from the scene too, dirty or not: here
// the GL positions are posed but the scene stays at rest, and a host update with no dirty mesh brings
// the structures back to the scene's rest pose.
TEST_F(GlRefitTest, AHostUpdateAfterGpuRefitsFollowsTheScene) {
  Scene scene = testing::make_instanced_scene(16);
  GlRayTracer tracer;
  tracer.build(scene, {});
  const std::vector<accel::Ray> rays = random_rays(scene, 800, 9);
  const std::vector<accel::Hit> rest = brute_force_hits(scene, rays);
  Scene posed = scene;
  SceneDeformers deformers(posed);
  const std::vector<uint32_t> dirty = deformers.apply(posed, 30);
  write_gl_positions(*tracer.gl_tracing(), posed, dirty);
  tracer.update_gl(dirty, UpdatePolicy::refit);
  ASSERT_EQ(compare_hits(posed, rays, brute_force_hits(posed, rays), trace(tracer, rays)), "");
  tracer.update(scene, {}, UpdatePolicy::refit);
  EXPECT_EQ(compare_hits(scene, rays, rest, trace(tracer, rays)), "");
  EXPECT_TRUE(tracer.stats().blas_sah_drift.has_value()) << "the host's BVHs are current again";
  HostStructures host(scene, {});
  (void)host.blases.update(scene, dirty, UpdatePolicy::refit);
  host.tlas = accel::build_tlas(host.blases.blases(), host.tlas.instances, accel::BvhBuilder::sah);
  expect_structures_equal(tracer, host, "host update");
}

TEST_F(GlRefitTest, UpdateGlRefusesWhatItCannotDo) {
  Scene scene = testing::make_instanced_scene();
  GlRayTracer tracer;
  const std::vector<uint32_t> sheet{2};
  EXPECT_NE(testing::error_of([&] { tracer.update_gl(sheet, UpdatePolicy::refit); }).find("before build()"),
            std::string::npos);
  tracer.build(scene, {});
  const std::vector<uint32_t> past{static_cast<uint32_t>(scene.meshes.size())};
  EXPECT_NE(testing::error_of([&] { tracer.update_gl(past, UpdatePolicy::refit); }).find("out of range"),
            std::string::npos);
  EXPECT_NE(testing::error_of([&] { (void)tracer.gl_positions(99); }).find("out of range"), std::string::npos);
  // sbvh cannot be refitted: refit and automatic are refused before anything changes, rebuild works
  // (GlGpuUpdatePolicies.*).
  rt::AccelOptions sbvh;
  sbvh.builder = accel::BvhBuilder::sbvh;
  tracer.build(scene, sbvh);
  for (UpdatePolicy policy : {UpdatePolicy::refit, UpdatePolicy::automatic}) {
    EXPECT_NE(testing::error_of([&] { tracer.update_gl(sheet, policy); }).find("sbvh"), std::string::npos);
  }
  EXPECT_EQ(tracer.stats().refits + tracer.stats().rebuilds, 0u);
}

}  // namespace
}  // namespace glint::gl_rt
