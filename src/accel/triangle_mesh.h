#pragma once
// A non-owning view of triangles, the only geometry accel/ knows. Usable on the device: two
// pointers and a count. Traversal reads the three corners of a triangle; refit re-reads them after
// the vertices moved (the topology, i.e. the index buffer, must stay the same).
#include "core/math.h"

#include <cstdint>
#include <span>
#include <type_traits>

namespace glint::accel {

struct Triangle {
  vec3 v0, v1, v2;

  GLINT_HOST_DEVICE Aabb bounds() const {
    Aabb box;
    box.extend(v0);
    box.extend(v1);
    box.extend(v2);
    return box;
  }
};

// Two layouts in one view: indexed (indices != nullptr: triangle i uses positions[indices[3i+k]])
// or pre-gathered (indices == nullptr: triangle i is positions[3i], positions[3i+1], positions[3i+2]),
// the latter saving one indirection per triangle during traversal.
struct TriangleMesh {
  const vec3* positions = nullptr;
  const uint32_t* indices = nullptr;
  uint32_t vertex_count = 0;
  uint32_t triangle_count = 0;

  GLINT_HOST_DEVICE Triangle triangle(uint32_t i) const {
    if (indices != nullptr) {
      const uint32_t* tri = indices + 3 * static_cast<size_t>(i);
      return {positions[tri[0]], positions[tri[1]], positions[tri[2]]};
    }
    const vec3* tri = positions + 3 * static_cast<size_t>(i);
    return {tri[0], tri[1], tri[2]};
  }
};

static_assert(std::is_trivially_copyable_v<TriangleMesh>);

// Checked constructors: an index buffer whose size is not a multiple of 3, an index past the last
// vertex, or more than 2^32 - 1 elements throw glint::Error.
TriangleMesh make_indexed_mesh(std::span<const vec3> positions, std::span<const uint32_t> indices);
TriangleMesh make_triangle_soup(std::span<const vec3> gathered_positions);

}  // namespace glint::accel
