// Polygonal OBJ faces split into triangles: concave polygons keep their shape (tinyobjloader's own
// triangulation covered an L-shaped floor's notch and turned the same L, listed from another corner,
// into two slivers), faces keep their winding, and OBJ files with such faces load as drawn.
#include "scene/polygon_triangulation.h"

#include "core/log.h"
#include "scene/obj_loader.h"
#include "support/error_of.h"
#include "support/temp_folder.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace glint {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

// Twice the signed area of a triangle in the y = 0 plane, seen from +y (positive: counter-clockwise).
double signed_area_xz(const vec3& a, const vec3& b, const vec3& c) {
  return 0.5 * static_cast<double>(glm::cross(b - a, c - a).y);
}

double area(const vec3& a, const vec3& b, const vec3& c) { return 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a))); }

bool inside_triangle_xz(const vec3& p, const vec3& a, const vec3& b, const vec3& c) {
  const auto side = [](const vec3& u, const vec3& v, const vec3& q) { return (v.x - u.x) * (q.z - u.z) - (v.z - u.z) * (q.x - u.x); };
  const float d1 = side(a, b, p), d2 = side(b, c, p), d3 = side(c, a, p);
  return (d1 > 0 && d2 > 0 && d3 > 0) || (d1 < 0 && d2 < 0 && d3 < 0);
}

// The L of the OBJ files below: the square [0, 4] x [-4, 0] (x, z) without [1, 4] x [-3, 0], area 7,
// counter-clockwise seen from +y, listed starting at `first`.
std::vector<vec3> l_shape(std::size_t first) {
  const std::vector<vec3> corners = {{0, 0, 0}, {1, 0, 0}, {1, 0, -3}, {4, 0, -3}, {4, 0, -4}, {0, 0, -4}};
  std::vector<vec3> rotated;
  for (std::size_t i = 0; i < corners.size(); ++i) rotated.push_back(corners[(first + i) % corners.size()]);
  return rotated;
}

TEST(PolygonTriangulation, AnLShapeFromEveryStartingCornerCoversExactlyItsArea) {
  for (std::size_t first = 0; first < 6; ++first) {
    const std::vector<vec3> corners = l_shape(first);
    const Triangles triangles = triangulate_polygon(corners);
    ASSERT_EQ(triangles.size(), 4u) << "first corner " << first;
    double total = 0.0;
    for (const auto& t : triangles) {
      const double signed_area = signed_area_xz(corners[t[0]], corners[t[1]], corners[t[2]]);
      EXPECT_GT(signed_area, 0.0) << "first corner " << first << ": a triangle is flipped or flat";
      total += signed_area;
      // Nothing of the notch [1, 4] x [-3, 0] is covered.
      EXPECT_FALSE(inside_triangle_xz(vec3(2.5f, 0, -1.5f), corners[t[0]], corners[t[1]], corners[t[2]]))
          << "first corner " << first;
    }
    EXPECT_NEAR(total, 7.0, 1e-9) << "first corner " << first;
  }
}

TEST(PolygonTriangulation, AConcaveQuadIsSplitThroughItsNotch) {
  // An arrow head: corner 3 points inwards, so the shorter diagonal (0-2) runs outside it.
  const std::vector<vec3> corners = {{0, 0, 0}, {4, 0, -1}, {0, 0, -2}, {1, 0, -1}};
  const Triangles triangles = triangulate_polygon(corners);
  ASSERT_EQ(triangles.size(), 2u);
  double total = 0.0;
  for (const auto& t : triangles) {
    const double signed_area = signed_area_xz(corners[t[0]], corners[t[1]], corners[t[2]]);
    EXPECT_GT(signed_area, 0.0);
    total += signed_area;
  }
  EXPECT_NEAR(total, 3.0, 1e-9);  // the triangle (0,1,2) of area 4 less the notch (0,3,2) of area 1
}

TEST(PolygonTriangulation, AConvexQuadIsSplitAlongItsShorterDiagonal) {
  // A kite whose diagonal 1-3 is the short one, then one whose 0-2 is.
  const std::vector<vec3> long02 = {{0, 0, 0}, {1, 0, -1}, {0, 0, -4}, {-1, 0, -1}};
  const std::vector<vec3> short02 = {{0, 0, 0}, {4, 0, -1}, {0, 0, -2}, {-4, 0, -1}};
  const auto uses_diagonal = [](const Triangles& triangles, std::uint32_t a, std::uint32_t b) {
    return std::all_of(triangles.begin(), triangles.end(), [&](const auto& t) {
      return std::find(t.begin(), t.end(), a) != t.end() && std::find(t.begin(), t.end(), b) != t.end();
    });
  };
  EXPECT_TRUE(uses_diagonal(triangulate_polygon(long02), 1, 3));
  EXPECT_TRUE(uses_diagonal(triangulate_polygon(short02), 0, 2));
}

TEST(PolygonTriangulation, KeepsTheWindingOfAClockwisePolygonInATiltedPlane) {
  // The L listed clockwise seen from +y (it faces down), rotated out of any axis plane and moved
  // far from the origin: every triangle must still face down the same way, and the notch stay empty.
  std::vector<vec3> corners = l_shape(2);
  std::reverse(corners.begin(), corners.end());
  const glm::mat3 tilt = glm::mat3(glm::vec3(0.8f, 0.6f, 0.0f), glm::vec3(-0.6f, 0.8f, 0.0f), glm::vec3(0, 0, 1));
  std::vector<vec3> tilted;
  for (const vec3& corner : corners) tilted.push_back(tilt * corner + vec3(1e5f, -3e4f, 2e4f));
  const Triangles triangles = triangulate_polygon(tilted);
  ASSERT_EQ(triangles.size(), 4u);
  const vec3 down = tilt * vec3(0, -1, 0);
  double total = 0.0;
  for (const auto& t : triangles) {
    const vec3 n = glm::cross(tilted[t[1]] - tilted[t[0]], tilted[t[2]] - tilted[t[0]]);
    EXPECT_GT(glm::dot(n, down), 0.0f);
    total += area(tilted[t[0]], tilted[t[1]], tilted[t[2]]);
  }
  EXPECT_NEAR(total, 7.0, 0.05);  // float corners at 1e5 are 0.008 apart
}

TEST(PolygonTriangulation, PointsOnAnEdgeStayCornersOfNonDegenerateTriangles) {
  // A square with a corner in the middle of each edge, as exporters write to avoid T-junctions.
  const std::vector<vec3> corners = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 0, -1}, {2, 0, -2}, {1, 0, -2}, {0, 0, -2}, {0, 0, -1}};
  const Triangles triangles = triangulate_polygon(corners);
  ASSERT_EQ(triangles.size(), 6u);
  std::vector<bool> used(corners.size(), false);
  double total = 0.0;
  for (const auto& t : triangles) {
    const double signed_area = signed_area_xz(corners[t[0]], corners[t[1]], corners[t[2]]);
    EXPECT_GT(signed_area, 0.0);
    total += signed_area;
    for (const std::uint32_t k : t) used[k] = true;
  }
  EXPECT_NEAR(total, 4.0, 1e-9);
  EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
}

TEST(PolygonTriangulation, AHoleJoinedToTheOutlineByABridgeStaysOpen) {
  // A 2 x 2 square with a 1 x 1 hole, written as one polygon that runs from the outline's last
  // corner to the hole, around it the other way, and back (as CAD exporters write holes).
  const std::vector<vec3> outline = {{0, 0, 0}, {2, 0, 0}, {2, 0, -2}, {0, 0, -2}};
  const std::vector<vec3> hole = {{0.5f, 0, -0.5f}, {1.5f, 0, -0.5f}, {1.5f, 0, -1.5f}, {0.5f, 0, -1.5f}};
  const std::vector<vec3> corners = {outline[0], outline[1], outline[2], outline[3], hole[3],
                                     hole[2],    hole[1],    hole[0],    hole[3],    outline[3]};
  const Triangles triangles = triangulate_polygon(corners);
  ASSERT_EQ(triangles.size(), corners.size() - 2);
  double total = 0.0;
  for (const auto& t : triangles) {
    const double signed_area = signed_area_xz(corners[t[0]], corners[t[1]], corners[t[2]]);
    EXPECT_GE(signed_area, 0.0);
    total += signed_area;
    EXPECT_FALSE(inside_triangle_xz(vec3(1.0f, 0, -1.0f), corners[t[0]], corners[t[1]], corners[t[2]])) << "the hole is covered";
  }
  EXPECT_NEAR(total, 3.0, 1e-9);
}

TEST(PolygonTriangulation, SelfIntersectingAndFlatPolygonsEndWithAtMostNMinusTwoTriangles) {
  const std::vector<vec3> bow_tie = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}, {1, 0, -1}, {0.5f, 0, 0.5f}};
  EXPECT_LE(triangulate_polygon(bow_tie).size(), 3u);
  const std::vector<vec3> line = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}};
  EXPECT_EQ(triangulate_polygon(line).size(), 2u);
  const std::vector<vec3> same_point(5, vec3(1, 2, 3));
  EXPECT_EQ(triangulate_polygon(same_point).size(), 3u);
}

TEST(PolygonTriangulation, AStarShapedFaceOfManyCornersKeepsItsArea) {
  // 200 spikes: every other corner reflex.
  std::vector<vec3> corners;
  double expected = 0.0;
  const std::size_t n = 400;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    const float radius = i % 2 == 0 ? 1.0f : 0.5f;
    corners.emplace_back(radius * static_cast<float>(std::cos(angle)), 0.0f, -radius * static_cast<float>(std::sin(angle)));
  }
  for (std::size_t i = 0; i < n; ++i) expected += signed_area_xz(vec3(0), corners[i], corners[(i + 1) % n]);
  const Triangles triangles = triangulate_polygon(corners);
  ASSERT_EQ(triangles.size(), n - 2);
  double total = 0.0;
  for (const auto& t : triangles) {
    const double signed_area = signed_area_xz(corners[t[0]], corners[t[1]], corners[t[2]]);
    EXPECT_GT(signed_area, 0.0);
    total += signed_area;
  }
  EXPECT_NEAR(total, expected, 1e-4);
}

TEST(PolygonTriangulation, RandomStarShapedPolygonsKeepTheirAreaAndAnyPolygonEnds) {
  // Star-shaped polygons (random radii at increasing angles) are simple: their triangles must cover
  // exactly their area, all wound alike. Random points in any order only have to end, in range.
  std::mt19937 random(20261126);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 4 + static_cast<std::size_t>(trial % 60);
    std::vector<vec3> star, scattered;
    for (std::size_t i = 0; i < n; ++i) {
      const double angle = 2.0 * std::numbers::pi * (static_cast<double>(i) + 0.8 * unit(random)) / static_cast<double>(n);
      const float radius = 0.1f + unit(random);
      star.emplace_back(radius * static_cast<float>(std::cos(angle)), 0.0f, -radius * static_cast<float>(std::sin(angle)));
      scattered.emplace_back(unit(random), unit(random) * (trial % 3 == 0 ? 0.0f : 1.0f), unit(random));
    }
    double expected = 0.0;
    for (std::size_t i = 0; i < n; ++i) expected += signed_area_xz(vec3(0), star[i], star[(i + 1) % n]);
    const Triangles triangles = triangulate_polygon(star);
    ASSERT_EQ(triangles.size(), n - 2) << "trial " << trial;
    double total = 0.0;
    for (const auto& t : triangles) {
      const double signed_area = signed_area_xz(star[t[0]], star[t[1]], star[t[2]]);
      EXPECT_GE(signed_area, 0.0) << "trial " << trial;
      total += signed_area;
    }
    EXPECT_NEAR(total, expected, 1e-5 * expected) << "trial " << trial;
    const Triangles any = triangulate_polygon(scattered);
    EXPECT_LE(any.size(), n - 2) << "trial " << trial;
    for (const auto& t : any)
      for (const std::uint32_t k : t) EXPECT_LT(k, n) << "trial " << trial;
  }
}

TEST(ObjPolygonFaces, AConcavePolygonAndRelativeIndicesLoadAsDrawn) {
  // An L-shaped floor written from a reflex corner, and a wall quad with negative (relative)
  // indices; no normals, no texture coordinates, no materials.
  testing::TempFolder folder;
  const auto obj = folder.write("l.obj",
                                "v 0 0 0\nv 1 0 0\nv 1 0 -3\nv 4 0 -3\nv 4 0 -4\nv 0 0 -4\n"
                                "f 3 4 5 6 1 2\n"
                                "v 0 0 -4\nv 4 0 -4\nv 4 2 -4\nv 0 2 -4\n"
                                "f -4 -3 -2 -1\n");
  const ScopedLogCapture quiet;
  const Scene scene = load_obj(obj);
  ASSERT_EQ(scene.meshes.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  ASSERT_EQ(mesh.triangle_count(), 6u);
  double floor = 0.0, wall = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    const vec3 &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]], &c = mesh.positions[mesh.indices[t + 2]];
    if (a.y == 0 && b.y == 0 && c.y == 0) {
      const double signed_area = signed_area_xz(a, b, c);
      EXPECT_GT(signed_area, 0.0) << "a floor triangle faces down";
      EXPECT_FALSE(inside_triangle_xz(vec3(2.5f, 0, -1.5f), a, b, c)) << "a floor triangle covers the notch";
      floor += signed_area;
    } else {
      EXPECT_GT(glm::cross(b - a, c - a).z, 0.0f) << "a wall triangle faces away from +z";
      wall += area(a, b, c);
    }
  }
  EXPECT_NEAR(floor, 7.0, 1e-6);
  EXPECT_NEAR(wall, 8.0, 1e-6);
  // Computed normals face up on the floor.
  for (std::size_t v = 0; v < mesh.positions.size(); ++v)
    if (mesh.positions[v].y == 0 && mesh.positions[v].x > 0.5f && mesh.positions[v].z > -3.5f) {
      EXPECT_GT(mesh.normals[v].y, 0.9f);
    }
}

TEST(ObjPolygonFaces, AFaceOfMoreThan255VerticesKeepsThemAll) {
  // tinyobjloader counts a face's vertices in 8 bits: a 300-gon came back as 44 vertices.
  std::string text;
  const std::size_t n = 300;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    text += fmt::format("v {:.7f} {:.7f} 0\n", std::cos(angle), std::sin(angle));
  }
  text += "f";
  for (std::size_t i = 1; i <= n; ++i) text += fmt::format(" {}", i);
  testing::TempFolder folder;
  const ScopedLogCapture quiet;
  const Scene scene = load_obj(folder.write("circle.obj", text + "\n"));
  EXPECT_EQ(scene.triangle_count(), n - 2);
  EXPECT_EQ(scene.vertex_count(), n);
}

TEST(ObjPolygonFaces, AFaceLineTinyobjloaderDoesNotReadIsAnError) {
  // "f\v1 2 3" is a face to the validation pass but not to tinyobjloader: the faces' vertex counts
  // would then be applied to the wrong faces.
  testing::TempFolder folder;
  const auto obj = folder.write("tab.obj", std::string("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf\v1 2 3\nf 1 2 4 3\n"));
  const ScopedLogCapture quiet;
  const std::string message = testing::error_of([&] { load_obj(obj); });
  EXPECT_NE(message.find("tab.obj: tinyobjloader read 1 faces with 4 vertex references where glint read 2 'f' lines"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace glint
