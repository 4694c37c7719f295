// OBJ files without normals say with `s` lines which faces are smoothed together: "s off" (or "s 0")
// faces are flat, "s N" faces are smooth within group N only. They were all smoothed across every
// shared vertex, so a low-poly box exported with "s off" and no normals rendered as a blob.
#include "scene/obj_loader.h"

#include "core/log.h"
#include "support/temp_folder.h"

#include <gtest/gtest.h>

#include <string>

namespace glint {
namespace {

// A 2-unit cube around the origin, 8 shared positions, 6 quads facing out, no normals; `top` is put
// before the top face's line, `sides` before the others.
std::string cube(const std::string& sides, const std::string& top) {
  return "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n" + sides +
         "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 1 2 6 5\n" + top + "f 4 8 7 3\n";
}

Mesh load_cube(const std::string& text) {
  testing::TempFolder folder;
  const ScopedLogCapture quiet;
  const Scene scene = load_obj(folder.write("cube.obj", text));
  EXPECT_EQ(scene.meshes.size(), 1u);
  return scene.meshes.at(0);
}

// The axis a triangle of the cube faces (its centroid's largest component, with sign).
vec3 face_axis(const Mesh& mesh, std::size_t t) {
  const vec3 centroid = (mesh.positions[mesh.indices[3 * t]] + mesh.positions[mesh.indices[3 * t + 1]] +
                         mesh.positions[mesh.indices[3 * t + 2]]) / 3.0f;
  vec3 axis(0.0f);
  const int k = std::abs(centroid.x) > 0.9f ? 0 : (std::abs(centroid.y) > 0.9f ? 1 : 2);
  axis[k] = centroid[k] > 0.0f ? 1.0f : -1.0f;
  return axis;
}

TEST(ObjSmoothingGroups, FacesUnderSmoothingOffAreFlat) {
  for (const char* off : {"s off\n", "s 0\n"}) {
    const Mesh mesh = load_cube(cube(off, ""));
    EXPECT_EQ(mesh.vertex_count(), 24u) << off;  // four corners per face, none shared
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t)
      for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(glm::dot(mesh.normals[mesh.indices[3 * t + k]], face_axis(mesh, t)), 1.0f, 1e-5f) << off << " triangle " << t;
  }
}

TEST(ObjSmoothingGroups, FacesOfOneGroupAreSmoothAndGroupsDoNotShareNormals) {
  // All in group 1: as without any `s` line, 8 smooth corners.
  EXPECT_EQ(load_cube(cube("s 1\n", "")).vertex_count(), 8u);
  EXPECT_EQ(load_cube(cube("", "")).vertex_count(), 8u);
  // The top face in group 2: its four corners are its own, facing straight up; the sides stay smooth.
  const Mesh mesh = load_cube(cube("s 1\n", "s 2\n"));
  EXPECT_EQ(mesh.vertex_count(), 12u);
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    const bool top = face_axis(mesh, t) == vec3(0, 1, 0);
    for (int k = 0; k < 3; ++k) {
      const vec3 n = mesh.normals[mesh.indices[3 * t + k]];
      if (top) {
        EXPECT_NEAR(n.y, 1.0f, 1e-5f) << "triangle " << t;
      } else {
        EXPECT_LT(std::abs(glm::dot(n, face_axis(mesh, t))), 0.99f) << "triangle " << t << ": a smooth corner";
      }
    }
  }
}

TEST(ObjSmoothingGroups, GivenNormalsWin) {
  // With normals in the file the groups change nothing: the corners keep the file's normals.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 1 0 -1\nv 0 0 -1\nvn 0 1 0\ns off\nf 1//1 2//1 3//1\nf 1//1 3//1 4//1\n";
  const Mesh mesh = load_cube(text);
  EXPECT_EQ(mesh.vertex_count(), 4u);
  for (const vec3& n : mesh.normals) EXPECT_EQ(n, vec3(0, 1, 0));
}

}  // namespace
}  // namespace glint
