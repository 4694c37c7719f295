// The two structures whose leaves hold references (kd-tree, SBVH) against brute force: random
// soups, watertight grids, axis-parallel rays and a soup made of degenerate cases, >100k rays each.
#include "accel/builders/build_sbvh.h"
#include "accel/kdtree/kdtree.h"
#include "accel/kdtree/kdtree_trace.h"
#include "accel/kdtree/kdtree_validate.h"
#include "accel/builders/primitive_bounds.h"
#include "accel/bvh_validate.h"
#include "accel/trace.h"
#include "accel/test_scenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

namespace glint::accel {
namespace {

using testing::TestMesh;

// Zero-area triangles (points, collinear), coplanar overlapping ones, exact duplicates, huge and
// tiny triangles, and flat axis-aligned triangles lying exactly on the planes where other
// triangles' boxes start and end (multiples of 0.25): the split candidates of every builder.
TestMesh make_degenerate_soup(uint32_t seed, uint32_t count) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  const auto grid = [&] { return std::round(u(rng) * 8.0f) * 0.25f; };
  const auto point = [&] { return vec3(u(rng), u(rng), u(rng)); };
  TestMesh mesh;
  while (mesh.triangle_count() < count) {
    const uint32_t kind = mesh.triangle_count() % 8;
    if (kind == 0) {  // a point
      const vec3 p = point();
      mesh.add_triangle(p, p, p);
    } else if (kind == 1) {  // collinear
      const vec3 a = point(), b = point();
      mesh.add_triangle(a, 0.5f * (a + b), b);
    } else if (kind == 2) {  // flat on a grid plane, box corners on grid planes too
      const int axis = static_cast<int>(rng() % 3);
      vec3 a(grid(), grid(), grid()), b(grid(), grid(), grid()), c(grid(), grid(), grid());
      a[axis] = b[axis] = c[axis] = grid();
      mesh.add_triangle(a, b, c);
    } else if (kind == 3) {  // coplanar overlapping pair in a tilted plane
      const vec3 o = point(), e1(0.3f, 0.1f, 0.05f), e2(-0.05f, 0.2f, 0.3f);
      mesh.add_triangle(o, o + e1, o + e2);
      if (mesh.triangle_count() < count) mesh.add_triangle(o + 0.1f * e1, o + 1.2f * e1, o + 0.9f * e2);
    } else if (kind == 4 && mesh.triangle_count() > 0) {  // exact duplicate, flipped winding
      const uint32_t source = static_cast<uint32_t>(rng() % mesh.triangle_count());
      const uint32_t* tri = &mesh.indices[3 * size_t{source}];
      mesh.add_triangle(tri[0], tri[2], tri[1]);
    } else if (kind == 5) {  // huge, through everything
      mesh.add_triangle(4.0f * point(), 4.0f * point(), 4.0f * point());
    } else if (kind == 6) {  // tiny
      const vec3 p = point();
      mesh.add_triangle(p, p + 1e-4f * point(), p + 1e-4f * point());
    } else {  // ordinary, with vertices on grid planes so box faces coincide with the flat ones
      mesh.add_triangle(vec3(grid(), grid(), grid()), vec3(grid(), grid(), grid()), point());
    }
  }
  return mesh;
}

struct Reference : testing::BruteForceReference {
  bool expect_all_hit = false;

  Reference(TestMesh scene, std::vector<Ray> scene_rays, bool all_hit)
      : BruteForceReference(std::move(scene), std::move(scene_rays)), expect_all_hit(all_hit) {}
};

// Same answer as brute force: same miss/hit; the same triangle with bit-identical t, u, v, or
// another triangle at the same t up to 1e-4 relative (shared edges, duplicates and coplanar
// overlaps are exact ties; the kd-tree's early exit may also take a triangle whose t differs from
// the closest by rounding across a split plane).
::testing::AssertionResult same_hit(const Hit& expected, const Hit& actual) {
  if (expected.valid() != actual.valid())
    return ::testing::AssertionFailure() << (expected.valid() ? "missed" : "spurious hit") << " (expected t "
                                         << expected.t << ", got " << actual.t << ")";
  if (!expected.valid()) return ::testing::AssertionSuccess();
  const float tolerance = 1e-4f * std::max(1.0f, std::abs(expected.t));
  if (std::abs(expected.t - actual.t) > tolerance)
    return ::testing::AssertionFailure() << "t " << actual.t << " (prim " << actual.prim << ") instead of "
                                         << expected.t << " (prim " << expected.prim << ")";
  if (actual.instance != 0) return ::testing::AssertionFailure() << "instance " << actual.instance;
  // The same triangle under the same ray gives bit-identical results in every structure.
  if (actual.prim == expected.prim && (actual.t != expected.t || actual.u != expected.u || actual.v != expected.v))
    return ::testing::AssertionFailure() << "same prim " << actual.prim << ", different t/u/v";
  return ::testing::AssertionSuccess();
}

const Reference& soup_reference() {
  static const Reference reference = [] {
    TestMesh soup = testing::make_random_soup(61, 4000);
    std::vector<Ray> rays = testing::make_random_rays(soup, 62, 30000);
    return Reference(std::move(soup), std::move(rays), false);
  }();
  return reference;
}

const Reference& grid_reference() {
  static const Reference reference = [] {
    testing::StackedGrids grids = testing::make_stacked_grids(24, 63, 64);
    return Reference(std::move(grids.mesh), std::move(grids.rays), true);
  }();
  return reference;
}

const Reference& axis_reference() {
  static const Reference reference = [] {
    TestMesh soup = testing::make_random_soup(65, 3000);
    testing::RayOptions options;
    options.axis_aligned_fraction = 0.6f;
    options.zero_component_fraction = 0.4f;
    std::vector<Ray> rays = testing::make_random_rays(soup, 66, 30000, options);
    // Origins exactly on the planes of the axis-aligned triangles (multiples of 0.25).
    for (size_t i = 0; i < rays.size(); i += 3) rays[i].origin = glm::round(rays[i].origin * 4.0f) * 0.25f;
    return Reference(std::move(soup), std::move(rays), false);
  }();
  return reference;
}

const Reference& degenerate_reference() {
  static const Reference reference = [] {
    TestMesh soup = make_degenerate_soup(67, 3000);
    testing::RayOptions options;
    options.axis_aligned_fraction = 0.3f;
    options.zero_component_fraction = 0.2f;
    std::vector<Ray> rays = testing::make_random_rays(soup, 68, 40000, options);
    for (size_t i = 0; i < rays.size(); i += 4) rays[i].origin = glm::round(rays[i].origin * 4.0f) * 0.25f;
    return Reference(std::move(soup), std::move(rays), false);
  }();
  return reference;
}

enum class Structure { sbvh_leaf1, sbvh_leaf4, sbvh_alpha0, kdtree, kdtree_cheap_traversal };

std::string structure_name(Structure structure) {
  switch (structure) {
    case Structure::sbvh_leaf1: return "sbvh_leaf1";
    case Structure::sbvh_leaf4: return "sbvh_leaf4";
    case Structure::sbvh_alpha0: return "sbvh_alpha0";
    case Structure::kdtree: return "kdtree";
    case Structure::kdtree_cheap_traversal: return "kdtree_cheap_traversal";
  }
  return "unknown";
}

class ReferenceStructures : public ::testing::TestWithParam<Structure> {
protected:
  // Builds the structure, checks it, traces closest and any hit.
  void trace(const TriangleMesh& mesh, const std::vector<Ray>& rays, std::vector<Hit>& hits,
             std::vector<uint8_t>& occluded) {
    hits.assign(rays.size(), Hit{});
    occluded.assign(rays.size(), 0);
    const Structure structure = GetParam();
    if (structure == Structure::kdtree || structure == Structure::kdtree_cheap_traversal) {
      KdTreeOptions options;
      options.parallel_threshold = 512;
      if (structure == Structure::kdtree_cheap_traversal) options.traversal_cost = 0.1f;  // deep trees
      const KdTree tree = build_kdtree(mesh, options);
      EXPECT_NO_THROW(validate_kdtree(tree, mesh, kdtree_depth_limit(mesh.triangle_count, options)));
      trace_closest(tree, mesh, rays, hits);
      trace_any(tree, mesh, rays, occluded);
      return;
    }
    BuildOptions options;
    options.max_leaf_size = structure == Structure::sbvh_leaf4 ? 4 : 1;
    options.parallel_threshold = 512;
    SbvhOptions sbvh;
    if (structure == Structure::sbvh_alpha0) sbvh.alpha = 0.0f;
    const Bvh bvh = build_sbvh(mesh, options, sbvh);
    EXPECT_NO_THROW(validate_bvh(bvh, triangle_bounds(mesh).boxes, options.max_leaf_size));
    EXPECT_NO_THROW(validate_sbvh_references(bvh, mesh, sbvh.reference_budget));
    trace_closest(bvh, mesh, rays, hits);
    trace_any(bvh, mesh, rays, occluded);
  }

  void check(const Reference& reference) {
    std::vector<Hit> hits;
    std::vector<uint8_t> occluded;
    trace(reference.mesh.view(), reference.rays, hits, occluded);
    size_t failures = 0, hit_count = 0;
    for (size_t i = 0; i < reference.rays.size() && failures < 10; ++i) {
      const auto same = same_hit(reference.closest[i], hits[i]);
      EXPECT_TRUE(same) << "ray " << i;
      EXPECT_EQ(occluded[i] != 0, hits[i].valid()) << "ray " << i << ": any hit disagrees with closest hit";
      if (reference.expect_all_hit) {
        EXPECT_TRUE(hits[i].valid()) << "ray " << i << " slipped through";
      }
      failures += same ? 0 : 1;
      hit_count += hits[i].valid() ? 1 : 0;
    }
    EXPECT_GT(hit_count, reference.rays.size() / 4);  // the rays do test something
  }
};

TEST_P(ReferenceStructures, RandomSoup) { check(soup_reference()); }
TEST_P(ReferenceStructures, GridEdgesAndVerticesAreWatertight) { check(grid_reference()); }
TEST_P(ReferenceStructures, AxisParallelRays) { check(axis_reference()); }
TEST_P(ReferenceStructures, DegenerateSoup) { check(degenerate_reference()); }

TEST(KdTreeTraversal, RayInASplitPlaneChecksTheTwinCellBeforeStopping) {
  // A hand-made tree: the root splits y at 0; the above leaf holds a square at z = 2, the below
  // leaf one at z = 1. A ray along +z inside the plane y = 0 visits the above leaf first (its hit
  // lies inside that leaf's t range) but must still visit the below leaf, which shares the same t
  // range and holds the closer hit.
  TestMesh scene;
  for (float z : {2.0f, 1.0f}) {
    scene.add_triangle(vec3(-1, -1, z), vec3(1, -1, z), vec3(1, 1, z));
    scene.add_triangle(vec3(-1, -1, z), vec3(1, 1, z), vec3(-1, 1, z));
  }
  const TriangleMesh mesh = scene.view();
  KdTree tree;
  tree.prim_count = 4;
  tree.bounds = scene.bounds();
  tree.depth = 2;
  tree.nodes = {KdNode::interior(1, 0.0f, 2), KdNode::leaf(0, 2), KdNode::leaf(2, 2)};
  tree.prim_indices = {2, 3, 0, 1};  // below: the z = 1 square; above: the z = 2 square
  const Ray ray{vec3(0.1f, 0.0f, 0.0f), 0.0f, vec3(0.0f, 0.0f, 1.0f), kInfinity};
  Hit hit;
  trace_closest(tree, mesh, std::span(&ray, 1), std::span(&hit, 1));
  ASSERT_TRUE(hit.valid());
  EXPECT_EQ(hit.t, 1.0f);
  EXPECT_GE(hit.prim, 2u);
}

TEST(ReferenceStructuresRays, MoreThan100kPerStructure) {
  const size_t total = soup_reference().rays.size() + grid_reference().rays.size() + axis_reference().rays.size() +
                       degenerate_reference().rays.size();
  EXPECT_GE(total, 100000u);
}

INSTANTIATE_TEST_SUITE_P(Accel, ReferenceStructures,
                         ::testing::Values(Structure::sbvh_leaf1, Structure::sbvh_leaf4, Structure::sbvh_alpha0,
                                           Structure::kdtree, Structure::kdtree_cheap_traversal),
                         [](const ::testing::TestParamInfo<Structure>& param_info) {
                           return structure_name(param_info.param);
                         });

}  // namespace
}  // namespace glint::accel
