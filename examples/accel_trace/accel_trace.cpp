// glint::accel as a library: a BVH over a few triangles built with two of glint's builders, a ray
// traced through it (closest hit and occlusion), the BVH refitted after the triangles moved.
#include "accel/builders/builder.h"
#include "accel/bvh_stats.h"
#include "accel/refit.h"
#include "accel/trace.h"
#include "accel/triangle_mesh.h"
#include "core/error.h"

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using glint::vec3;
namespace accel = glint::accel;

int main() {
  // Three triangles across the z axis at z = 3, 2 and 5: a ray from the origin along +z meets
  // triangle 1 first, at t = 2.
  std::vector<vec3> positions;
  std::vector<uint32_t> indices;
  for (const float z : {3.0f, 2.0f, 5.0f}) {
    const auto first = static_cast<uint32_t>(positions.size());
    positions.insert(positions.end(), {vec3(-1.0f, -1.0f, z), vec3(1.0f, -1.0f, z), vec3(0.0f, 1.0f, z)});
    indices.insert(indices.end(), {first, first + 1, first + 2});
  }
  try {
    const accel::TriangleMesh mesh = accel::make_indexed_mesh(positions, indices);
    std::vector<accel::Ray> rays(1);
    rays[0].origin = vec3(0.0f);
    rays[0].direction = vec3(0.0f, 0.0f, 1.0f);
    std::vector<accel::Hit> hits(rays.size());
    std::vector<uint8_t> occluded(rays.size());

    for (const accel::BvhBuilder builder : {accel::BvhBuilder::sah, accel::BvhBuilder::lbvh}) {
      accel::Bvh bvh = accel::build_bvh(builder, mesh);
      accel::trace_closest(bvh, mesh, rays, hits);
      accel::trace_any(bvh, mesh, rays, occluded);
      const accel::BvhStats stats = accel::compute_stats(bvh);
      std::printf("%s\n  closest hit: triangle %u at t = %g, occluded: %d\n",
                  accel::format_stats(std::string(accel::builder_name(builder)), stats).c_str(), hits[0].prim,
                  hits[0].t, occluded[0]);
    }

    // Move triangle 1 behind the others (z = 6) and refit: the ray now hits triangle 0 at t = 3.
    accel::Bvh bvh = accel::build_bvh(accel::BvhBuilder::sah, mesh);
    for (int k = 3; k < 6; ++k) positions[k].z = 6.0f;
    accel::refit(bvh, mesh);
    accel::trace_closest(bvh, mesh, rays, hits);
    std::printf("after refit: triangle %u at t = %g\n", hits[0].prim, hits[0].t);
    return hits[0].prim == 0 ? 0 : 1;
  } catch (const glint::Error& error) {
    std::fprintf(stderr, "accel_trace: %s\n", error.what());
    return 1;
  }
}
