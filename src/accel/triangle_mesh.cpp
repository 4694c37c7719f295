#include "accel/triangle_mesh.h"

#include "core/error.h"

#include <algorithm>
#include <limits>

namespace glint::accel {
namespace {

uint32_t checked_count(size_t count, const char* what) {
  if (count >= std::numeric_limits<uint32_t>::max()) fail("accel: too many {} ({}), at most 2^32 - 2", what, count);
  return static_cast<uint32_t>(count);
}

}  // namespace

TriangleMesh make_indexed_mesh(std::span<const vec3> positions, std::span<const uint32_t> indices) {
  if (indices.size() % 3 != 0) fail("accel: index buffer size {} is not a multiple of 3", indices.size());
  TriangleMesh mesh;
  mesh.positions = positions.data();
  mesh.indices = indices.data();
  mesh.vertex_count = checked_count(positions.size(), "vertices");
  mesh.triangle_count = checked_count(indices.size() / 3, "triangles");
  if (!indices.empty()) {
    const uint32_t largest = *std::max_element(indices.begin(), indices.end());
    if (largest >= mesh.vertex_count)
      fail("accel: index {} is out of range for {} vertices", largest, mesh.vertex_count);
  }
  return mesh;
}

TriangleMesh make_triangle_soup(std::span<const vec3> gathered_positions) {
  if (gathered_positions.size() % 3 != 0)
    fail("accel: triangle soup has {} vertices, not a multiple of 3", gathered_positions.size());
  TriangleMesh mesh;
  mesh.positions = gathered_positions.data();
  mesh.vertex_count = checked_count(gathered_positions.size(), "vertices");
  mesh.triangle_count = mesh.vertex_count / 3;
  return mesh;
}

}  // namespace glint::accel
