// The GPU builders (lbvh, ploc), GPU refit and depth through the plain host entry points
// (cuda/gpu_bvh_host.h): every downloaded structure must pass accel::validate_bvh and answer 100k
// random rays, traced on the CPU over it, exactly like the brute-force reference (same t; the same
// triangle unless another one lies at exactly that t). GPU tests skip without a CUDA GPU.
//
// References: brute force over every ray up to 10k triangles; above that (100k-triangle soup, the
// reduced atrium) brute force over 100k rays would take minutes, so the reference is the CPU `sah`
// BVH's answers (itself checked against brute force in tests/accel), checked here again against
// brute force on the first kBruteForceCheckRays rays.
#include "accel/builders/builder.h"
#include "accel/bvh_validate.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/refit.h"
#include "accel/test_scenes.h"
#include "accel/trace.h"
#include "core/error.h"
#include "cuda/device_query.h"
#include "cuda/gpu_bvh_host.h"
#include "rt/ray_tracer_check.h"
#include "rt/scene_geometry.h"
#include "scene/sine_deformer.h"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace glint {
namespace {

using accel::testing::TestMesh;
using cuda::GpuBvhBuilder;

constexpr size_t kRayCount = 100000;
constexpr uint32_t kBruteForceLimit = 10000;  // triangles; above it the reference is the CPU sah BVH
constexpr size_t kBruteForceCheckRays = 2000;

std::vector<accel::Hit> brute_force(const TestMesh& mesh, std::span<const accel::Ray> rays) {
  const accel::TriangleMesh view = mesh.view();
  std::vector<accel::Hit> hits(rays.size());
  tbb::parallel_for(tbb::blocked_range<size_t>(0, rays.size(), 256), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i) hits[i] = accel::testing::brute_force_closest(view, rays[i]);
  });
  return hits;
}

std::vector<accel::Hit> trace(const accel::Bvh& bvh, const TestMesh& mesh, std::span<const accel::Ray> rays) {
  std::vector<accel::Hit> hits(rays.size());
  accel::trace_closest(bvh, mesh.view(), rays, hits);
  return hits;
}

// "" when every hit equals the expected one (testing::same_closest_hit), else the first few
// differences and their count.
std::string compare(std::span<const accel::Hit> expected, std::span<const accel::Hit> hits) {
  std::string report;
  size_t differences = 0;
  for (size_t i = 0; i < expected.size(); ++i) {
    const ::testing::AssertionResult same = accel::testing::same_closest_hit(expected[i], hits[i]);
    if (!same && ++differences <= 5) report += "ray " + std::to_string(i) + ": " + same.message() + "\n";
  }
  if (differences > 0) report += std::to_string(differences) + " of " + std::to_string(expected.size()) + " rays differ";
  return report;
}

size_t hit_count(std::span<const accel::Hit> hits) {
  size_t count = 0;
  for (const accel::Hit& hit : hits) count += hit.valid() ? 1 : 0;
  return count;
}

// A scene with its rays and reference answers, computed once and shared by both builders.
struct Reference {
  TestMesh mesh;
  std::vector<accel::Ray> rays;
  std::vector<accel::Hit> closest;
};

std::unique_ptr<Reference> make_reference(TestMesh mesh, uint32_t ray_seed) {
  auto reference = std::make_unique<Reference>();
  reference->mesh = std::move(mesh);
  reference->rays = accel::testing::make_random_rays(reference->mesh, ray_seed, kRayCount);
  if (reference->mesh.triangle_count() <= kBruteForceLimit) {
    reference->closest = brute_force(reference->mesh, reference->rays);
    return reference;
  }
  const accel::Bvh sah = accel::build_bvh(accel::BvhBuilder::sah, reference->mesh.view());
  reference->closest = trace(sah, reference->mesh, reference->rays);
  const std::span<const accel::Ray> checked(reference->rays.data(), kBruteForceCheckRays);
  const std::string sah_report =
      compare(brute_force(reference->mesh, checked), std::span(reference->closest.data(), kBruteForceCheckRays));
  EXPECT_EQ(sah_report, "") << "the CPU sah reference itself";
  return reference;
}

// The built-in atrium-simple cut down (walls, beams, two creatures; tests/rt) in world space.
TestMesh flatten(const Scene& scene) {
  const rt::SceneGeometry geometry = rt::flatten_scene(scene);
  TestMesh mesh;
  mesh.positions = geometry.positions;
  mesh.indices = geometry.indices;
  return mesh;
}

const Reference& reference_scene(const std::string& name, uint32_t seed, uint32_t triangle_count) {
  static std::map<std::tuple<std::string, uint32_t, uint32_t>, std::unique_ptr<Reference>> scenes;
  std::unique_ptr<Reference>& scene = scenes[{name, seed, triangle_count}];
  if (!scene) {
    if (name == "random") scene = make_reference(accel::testing::make_random_soup(seed, triangle_count), seed + 1000);
    if (name == "degenerate")
      scene = make_reference(accel::testing::make_degenerate_soup(seed, triangle_count), seed + 1000);
    if (name == "atrium") scene = make_reference(flatten(testing::make_reduced_atrium()), seed + 1000);
  }
  return *scene;
}

std::vector<Aabb> boxes_of(const TestMesh& mesh) { return accel::triangle_bounds(mesh.view()).boxes; }

// Every vertex moved by smooth sines of the others' coordinates, `amplitude` times the scene size.
TestMesh sine_deformed(const TestMesh& mesh, float amplitude) {
  const Aabb box = mesh.bounds();
  const float size = glm::length(box.extent());
  const vec3 frequency = 6.2831853f / glm::max(box.extent(), vec3(1e-6f));
  TestMesh moved = mesh;
  for (vec3& p : moved.positions) {
    const vec3 phase = (p - box.min) * frequency;
    p += amplitude * size * vec3(std::sin(phase.y + 0.3f), std::sin(2.0f * phase.z + 1.1f), std::sin(phase.x - 0.7f));
  }
  return moved;
}

// Node for node: the same topology and bit-identical boxes.
::testing::AssertionResult same_structure(const accel::Bvh& expected, const accel::Bvh& actual) {
  if (expected.nodes.size() != actual.nodes.size())
    return ::testing::AssertionFailure() << actual.nodes.size() << " nodes instead of " << expected.nodes.size();
  if (expected.prim_indices != actual.prim_indices) return ::testing::AssertionFailure() << "prim_indices differ";
  for (size_t i = 0; i < expected.nodes.size(); ++i) {
    const accel::BvhNode &a = expected.nodes[i], &b = actual.nodes[i];
    if (a.first != b.first || a.prim_count != b.prim_count)
      return ::testing::AssertionFailure() << "node " << i << ": first " << b.first << " count " << b.prim_count
                                           << " instead of " << a.first << ", " << a.prim_count;
    if (a.bounds_min != b.bounds_min || a.bounds_max != b.bounds_max)
      return ::testing::AssertionFailure() << "node " << i << ": box differs";
  }
  if (expected.depth != actual.depth)
    return ::testing::AssertionFailure() << "depth " << actual.depth << " instead of " << expected.depth;
  return ::testing::AssertionSuccess();
}

// --- Without a GPU -------------------------------------------------------------------------------

TEST(GpuBvhNames, NamesAndParsingRoundTrip) {
  for (const GpuBvhBuilder builder : cuda::kAllGpuBvhBuilders)
    EXPECT_EQ(cuda::parse_gpu_builder(cuda::gpu_builder_name(builder)), builder);
  EXPECT_EQ(cuda::gpu_builder_name(GpuBvhBuilder::lbvh), "lbvh");
  EXPECT_EQ(cuda::gpu_builder_name(GpuBvhBuilder::ploc), "ploc");
  try {
    (void)cuda::parse_gpu_builder("sah");
    FAIL() << "expected glint::Error";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("\"sah\""), std::string::npos) << message;
    EXPECT_NE(message.find("lbvh, ploc"), std::string::npos) << message;
  }
}

TEST(GpuBvhWithoutGpu, EveryEntryPointIsOneClearError) {
  if (cuda_gpu_present()) GTEST_SKIP() << "this machine has a CUDA GPU";
  const TestMesh mesh = accel::testing::make_random_soup(1, 10);
  const accel::Bvh bvh = accel::build_bvh(accel::BvhBuilder::sah, mesh.view());
  const auto expect_cuda_error = [](auto&& call, const char* what) {
    try {
      call();
      ADD_FAILURE() << what << ": expected glint::Error";
    } catch (const Error& error) {
      EXPECT_NE(std::string(error.what()).find("CUDA"), std::string::npos) << what << ": " << error.what();
    }
  };
  expect_cuda_error([&] { (void)cuda::build_bvh_on_gpu(GpuBvhBuilder::lbvh, mesh.view()); }, "build_bvh_on_gpu");
  expect_cuda_error([&] { (void)cuda::refit_on_gpu(bvh, mesh.view()); }, "refit_on_gpu");
  const std::vector<std::vector<accel::TriangleMesh>> poses{{mesh.view()}};
  expect_cuda_error([&] { (void)cuda::refit_together_on_gpu(std::span<const accel::Bvh>(&bvh, 1), poses); },
                    "refit_together_on_gpu");
  expect_cuda_error([&] { (void)cuda::measure_depth_on_gpu(bvh); }, "measure_depth_on_gpu");
  expect_cuda_error([&] { cuda::GpuBvhSession session(GpuBvhBuilder::ploc); }, "GpuBvhSession");
}

// --- GPU builders ---------------------------------------------------------------------------------

class GpuBvhBuild : public ::testing::TestWithParam<GpuBvhBuilder> {
protected:
  void SetUp() override {
    if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  }

  // Builds on the GPU, validates (one primitive per leaf; the depth measured on the GPU must equal
  // the depth validate_bvh walks) and compares the CPU-traced hits with the reference.
  void expect_valid_with_reference_hits(const Reference& scene, const std::string& what) {
    const accel::Bvh bvh = cuda::build_bvh_on_gpu(GetParam(), scene.mesh.view());
    ASSERT_NO_THROW(accel::validate_bvh(bvh, boxes_of(scene.mesh), 1)) << what;
    EXPECT_EQ(bvh.builder, cuda::gpu_builder_name(GetParam()));
    EXPECT_LE(bvh.depth, accel::kMaxBvhDepth) << what;
    const std::vector<accel::Hit> hits = trace(bvh, scene.mesh, scene.rays);
    EXPECT_EQ(compare(scene.closest, hits), "") << what;
    if (scene.mesh.triangle_count() >= 100) {
      EXPECT_GT(hit_count(hits), kRayCount / 10) << what << ": rays hit something";
    }
  }
};

TEST_P(GpuBvhBuild, RandomSoupsOfEverySizeAreValidAndHitLikeTheReference) {
  for (const uint32_t size : {1u, 2u, 3u, 100u, 10000u})
    for (const uint32_t seed : {11u, 12u, 13u})
      expect_valid_with_reference_hits(reference_scene("random", seed, size),
                                       "random soup of " + std::to_string(size) + ", seed " + std::to_string(seed));
  expect_valid_with_reference_hits(reference_scene("random", 14, 100000), "random soup of 100000");
}

TEST_P(GpuBvhBuild, DegenerateSoupsAreValidAndHitLikeBruteForce) {
  // Zero-area triangles, duplicates, coplanar overlaps, huge and tiny ones, identical centroids.
  for (const uint32_t seed : {21u, 22u})
    expect_valid_with_reference_hits(reference_scene("degenerate", seed, 10000), "degenerate soup, seed " + std::to_string(seed));
}

TEST_P(GpuBvhBuild, ReducedAtriumIsValidAndHitsLikeTheReference) {
  const Reference& atrium = reference_scene("atrium", 31, 0);
  ASSERT_GT(atrium.mesh.triangle_count(), 1000u);
  expect_valid_with_reference_hits(atrium, "reduced atrium");
}

TEST_P(GpuBvhBuild, EmptyMeshGivesAnEmptyBvh) {
  const TestMesh empty;
  const accel::Bvh bvh = cuda::build_bvh_on_gpu(GetParam(), empty.view());
  EXPECT_TRUE(bvh.nodes.empty());
  EXPECT_TRUE(bvh.prim_indices.empty());
  EXPECT_EQ(bvh.depth, 0u);
  EXPECT_NO_THROW(accel::validate_bvh(bvh, {}, 1));
}

TEST_P(GpuBvhBuild, ShrinkingBoxesStayWithinTheDepthLimit) {
  // Boxes [s, 2s]^3 with s shrinking 3 % per triangle: greedy clustering merges them one at a time
  // into a chain 3000 deep unless the depth limit intervenes.
  TestMesh mesh;
  float size = 1.0f;
  for (int i = 0; i < 3000; ++i) {
    mesh.add_triangle(vec3(size), vec3(2.0f * size), vec3(2.0f * size, size, 2.0f * size));
    size *= 0.97f;
  }
  const accel::Bvh bvh = cuda::build_bvh_on_gpu(GetParam(), mesh.view());
  ASSERT_NO_THROW(accel::validate_bvh(bvh, boxes_of(mesh), 1));
  EXPECT_LE(bvh.depth, accel::kMaxBvhDepth);
  const std::vector<accel::Ray> rays = accel::testing::make_random_rays(mesh, 41, 20000);
  EXPECT_EQ(compare(brute_force(mesh, rays), trace(bvh, mesh, rays)), "");
}

TEST_P(GpuBvhBuild, AReusedSessionRebuildsExactlyLikeAFreshOne) {
  // Larger, smaller, then larger again: scratch and output are reused, nothing stale may leak in.
  // Both builders are deterministic, so the results must be identical node for node.
  cuda::GpuBvhSession session(GetParam());
  for (const auto& [seed, size] : {std::pair{51u, 20000u}, std::pair{52u, 300u}, std::pair{53u, 1u},
                                   std::pair{54u, 0u}, std::pair{55u, 15000u}}) {
    const TestMesh mesh = accel::testing::make_random_soup(seed, size);
    session.build(mesh.view());
    const accel::Bvh reused = session.download();
    EXPECT_TRUE(same_structure(cuda::build_bvh_on_gpu(GetParam(), mesh.view()), reused)) << size << " triangles";
    EXPECT_NO_THROW(accel::validate_bvh(reused, boxes_of(mesh), 1)) << size << " triangles";
  }
}

TEST_P(GpuBvhBuild, RefitAfterASineDeformationIsValidAndHitsLikeAFreshBuild) {
  const TestMesh soup = accel::testing::make_random_soup(61, 10000);
  Scene atrium_scene = testing::make_reduced_atrium();
  const TestMesh atrium = flatten(atrium_scene);
  SceneDeformers deformers(atrium_scene);
  ASSERT_FALSE(deformers.empty());
  (void)deformers.apply(atrium_scene, 2100);  // the creatures' sine deformer at frame 2100
  const TestMesh cases[][2] = {{soup, sine_deformed(soup, 0.02f)}, {atrium, flatten(atrium_scene)}};
  for (const auto& [rest, moved] : cases) {
    const std::string what = std::to_string(rest.triangle_count()) + " triangles";
    ASSERT_NE(rest.positions, moved.positions) << what;
    const accel::Bvh built = cuda::build_bvh_on_gpu(GetParam(), rest.view());
    const accel::Bvh refitted = cuda::refit_on_gpu(built, moved.view());
    ASSERT_NO_THROW(accel::validate_bvh(refitted, boxes_of(moved), 1)) << what;
    // Boxes are unions of the same floats on both sides: exactly the CPU refit of the same tree.
    accel::Bvh cpu_refitted = built;
    accel::refit(cpu_refitted, moved.view());
    EXPECT_TRUE(same_structure(cpu_refitted, refitted)) << what;

    const std::vector<accel::Ray> rays = accel::testing::make_random_rays(moved, 62, kRayCount);
    const accel::Bvh fresh = cuda::build_bvh_on_gpu(GetParam(), moved.view());
    const std::vector<accel::Hit> fresh_hits = trace(fresh, moved, rays);
    EXPECT_EQ(compare(fresh_hits, trace(refitted, moved, rays)), "") << what;
    EXPECT_GT(hit_count(fresh_hits), kRayCount / 10) << what;
    if (moved.triangle_count() <= kBruteForceLimit) {
      EXPECT_EQ(compare(brute_force(moved, rays), fresh_hits), "") << what;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(GpuBvh, GpuBvhBuild, ::testing::ValuesIn(cuda::kAllGpuBvhBuilders),
                         [](const ::testing::TestParamInfo<GpuBvhBuilder>& param_info) {
                           return std::string(cuda::gpu_builder_name(param_info.param));
                         });

// --- GPU refit and depth of CPU-built structures ----------------------------------------------------

TEST(GpuBvhRefit, CpuBuiltBvhsWithSeveralPrimitivesPerLeafEqualTheCpuRefitBoxForBox) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const TestMesh soup = accel::testing::make_random_soup(71, 20000);
  const TestMesh grid = accel::testing::make_grid(64, false);
  for (const TestMesh* rest : {&soup, &grid}) {
    const TestMesh moved = sine_deformed(*rest, 0.03f);
    for (const accel::BvhBuilder builder : {accel::BvhBuilder::sah, accel::BvhBuilder::median,
                                            accel::BvhBuilder::ploc, accel::BvhBuilder::none}) {
      accel::BuildOptions options;
      options.max_leaf_size = 4;
      const accel::Bvh built = accel::build_bvh(builder, rest->view(), options);
      const std::string what = std::string(accel::builder_name(builder)) + " over " +
                               std::to_string(rest->triangle_count()) + " triangles";
      if (builder != accel::BvhBuilder::none) {
        size_t multi = 0;
        for (const accel::BvhNode& node : built.nodes) multi += node.prim_count > 1 ? 1 : 0;
        ASSERT_GT(multi, 0u) << what << ": leaves with several primitives are what this test is about";
      }
      accel::Bvh cpu_refitted = built;
      accel::refit(cpu_refitted, moved.view());
      const accel::Bvh gpu_refitted = cuda::refit_on_gpu(built, moved.view());
      EXPECT_TRUE(same_structure(cpu_refitted, gpu_refitted)) << what;
      EXPECT_EQ(gpu_refitted.builder, built.builder);
    }
  }
}

// The frame's refit (refit_meshes_gpu): several BLASes in one launch, each leaf's box from its
// triangles, equal the CPU refit of each box for box, also at a second pose whose launch reuses the
// arrival counters the first left. Every counter must be 0 after each refit: one not set back would
// let the next climb pass a node before its sibling's box was refitted, which the boxes show only
// when the timing goes wrong; the counters show it every time.
TEST(GpuBvhRefit, SeveralMeshesRefittedInOneLaunchEqualTheCpuRefitAtEachPose) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const TestMesh soup = accel::testing::make_random_soup(71, 20000);
  const TestMesh grid = accel::testing::make_grid(64, false);
  const TestMesh tiny = accel::testing::make_random_soup(5, 7);
  const TestMesh single = accel::testing::make_random_soup(9, 1);
  const TestMesh* rests[] = {&soup, &grid, &tiny, &single};
  const accel::BvhBuilder builders[] = {accel::BvhBuilder::sah, accel::BvhBuilder::ploc, accel::BvhBuilder::median,
                                        accel::BvhBuilder::none};
  std::vector<accel::Bvh> built;
  std::vector<TestMesh> first, second;
  for (std::size_t i = 0; i < std::size(rests); ++i) {
    accel::BuildOptions options;
    options.max_leaf_size = 4;
    built.push_back(accel::build_bvh(builders[i], rests[i]->view(), options));
    first.push_back(sine_deformed(*rests[i], 0.03f));
    second.push_back(sine_deformed(*rests[i], -0.05f));
  }
  std::vector<std::vector<accel::TriangleMesh>> poses(2);
  for (std::size_t i = 0; i < built.size(); ++i) {
    poses[0].push_back(first[i].view());
    poses[1].push_back(second[i].view());
  }
  for (std::size_t count : {std::size_t{1}, std::size_t{2}}) {
    SCOPED_TRACE(::testing::Message() << count << " poses");
    const cuda::RefitTogetherResult refitted = cuda::refit_together_on_gpu(
        built, std::span<const std::vector<accel::TriangleMesh>>(poses.data(), count));
    ASSERT_EQ(refitted.bvhs.size(), built.size());
    ASSERT_EQ(refitted.arrival_counters.size(), built.size());
    for (std::size_t i = 0; i < built.size(); ++i) {
      accel::Bvh expected = built[i];
      accel::refit(expected, (count == 1 ? first[i] : second[i]).view());
      EXPECT_TRUE(same_structure(expected, refitted.bvhs[i])) << "mesh " << i;
      const std::vector<uint32_t>& counters = refitted.arrival_counters[i];
      EXPECT_EQ(counters.size(), built[i].nodes.size()) << "mesh " << i;
      EXPECT_EQ(std::count(counters.begin(), counters.end(), 0u), static_cast<std::ptrdiff_t>(counters.size()))
          << "mesh " << i << ": arrival counters left above 0";
    }
  }
}

TEST(GpuBvhRefit, RefusesSplitReferencesAndAnotherTriangleCount) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const TestMesh soup = accel::testing::make_random_soup(72, 2000);
  const accel::Bvh sbvh = accel::build_bvh(accel::BvhBuilder::sbvh, soup.view());
  ASSERT_FALSE(sbvh.refittable);
  EXPECT_THROW((void)cuda::refit_on_gpu(sbvh, soup.view()), Error);
  const TestMesh fewer = accel::testing::make_random_soup(72, 1999);
  const accel::Bvh sah = accel::build_bvh(accel::BvhBuilder::sah, soup.view());
  EXPECT_THROW((void)cuda::refit_on_gpu(sah, fewer.view()), Error);
}

TEST(GpuBvhDepth, MeasuredOnTheGpuEqualsTheCpuDepth) {
  if (!cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU";
  const TestMesh clustered = accel::testing::make_clustered(81, 30000);
  const TestMesh single = accel::testing::make_random_soup(82, 1);
  for (const TestMesh* mesh : {&clustered, &single}) {
    for (const accel::BvhBuilder builder : accel::kAllBvhBuilders) {
      for (const uint32_t leaf_size : {1u, 4u}) {
        accel::BuildOptions options;
        options.max_leaf_size = leaf_size;
        const accel::Bvh bvh = accel::build_bvh(builder, mesh->view(), options);
        EXPECT_EQ(cuda::measure_depth_on_gpu(bvh), bvh.depth)
            << accel::builder_name(builder) << ", leaf size " << leaf_size << ", " << mesh->triangle_count() << " triangles";
      }
    }
  }
  EXPECT_EQ(cuda::measure_depth_on_gpu(accel::Bvh{}), 0u);
}

}  // namespace
}  // namespace glint
