// glint::accel_cuda as a library: the example's triangles in a BVH built on the GPU (lbvh) and
// traced by glint's CUDA kernel. Needs a CUDA GPU: without one it prints glint's one-line reason and
// exits with 1.
#include "accel/builders/builder.h"
#include "accel/triangle_mesh.h"
#include "core/error.h"
#include "cuda/gpu_bench_structure.h"

#include <cstdint>
#include <cstdio>
#include <vector>

using glint::vec3;
namespace accel = glint::accel;

int main() {
  std::vector<vec3> positions;
  std::vector<uint32_t> indices;
  for (const float z : {3.0f, 2.0f, 5.0f}) {
    const auto first = static_cast<uint32_t>(positions.size());
    positions.insert(positions.end(), {vec3(-1.0f, -1.0f, z), vec3(1.0f, -1.0f, z), vec3(0.0f, 1.0f, z)});
    indices.insert(indices.end(), {first, first + 1, first + 2});
  }
  try {
    const accel::TriangleMesh mesh = accel::make_indexed_mesh(positions, indices);
    glint::cuda::GpuBenchStructure structure(accel::BvhBuilder::lbvh);
    structure.build(mesh);
    std::vector<accel::Ray> rays(1);
    rays[0].origin = vec3(0.0f);
    rays[0].direction = vec3(0.0f, 0.0f, 1.0f);
    std::vector<accel::Hit> hits(rays.size());
    structure.trace_closest(rays, hits);
    std::printf("cuda lbvh: closest hit: triangle %u at t = %g\n", hits[0].prim, hits[0].t);
    return hits[0].prim == 1 ? 0 : 1;
  } catch (const glint::Error& error) {
    std::fprintf(stderr, "accel_trace_cuda: %s\n", error.what());
    return 1;
  }
}
