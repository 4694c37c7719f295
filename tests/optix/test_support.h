#pragma once
// Shared by the Optix* tests: skipping where the optix backend cannot run (a build without OptiX,
// or no CUDA GPU: this is decided by the GPU machine run), and a hit comparison that sets aside the
// few rays grazing a triangle edge, where OptiX's and glint's intersection tests may round apart.
#include "accel/ray.h"
#include "cuda/device_query.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <span>
#include <vector>

// In a test body: skips unless this build has OptiX and a CUDA GPU is present. A present GPU whose
// driver cannot run these OptiX headers is not skipped: the test fails with optixInit's line.
#define GLINT_SKIP_WITHOUT_OPTIX_GPU()                                                        \
  do {                                                                                        \
    if (!GLINT_HAVE_OPTIX) GTEST_SKIP() << "glint was built without OptiX (OptiX_INSTALL_DIR)"; \
    if (!::glint::cuda_gpu_present()) GTEST_SKIP() << "no CUDA GPU on this machine";          \
  } while (0)

namespace glint::testing {

// The rays (and their two hit lists) left after setting aside every ray whose expected or actual hit
// lies within `edge_band` (barycentric) of an edge of its triangle. Such rays pass within float
// rounding of a neighbouring triangle or of the mesh's silhouette, where two correct watertight
// tests may disagree on hit/miss; `set_aside` says how many there were, for the caller to bound.
struct EdgeFilteredHits {
  std::vector<accel::Ray> rays;
  std::vector<accel::Hit> expected;
  std::vector<accel::Hit> actual;
  std::size_t set_aside = 0;
};

EdgeFilteredHits without_edge_grazing_rays(std::span<const accel::Ray> rays, std::span<const accel::Hit> expected,
                                           std::span<const accel::Hit> actual, float edge_band = 1e-4f);

// "" when `actual` equals `expected` for `scene` (compare_hits' rules) on every ray except those
// without_edge_grazing_rays sets aside and those that skim the surface they hit (|cos| < 0.02
// between the ray and the triangle's normal, where t and u, v are ill-conditioned), and those are at
// most 0.5 % of the rays; else why not. On the same triangle at the same t, u and v may differ by up
// to 1e-2 (OptiX's own barycentric rounding on small triangles).
std::string compare_hits_off_edges(const Scene& scene, std::span<const accel::Ray> rays,
                                   std::span<const accel::Hit> expected, std::span<const accel::Hit> actual);

// A scene with one mesh (every world triangle of `scene`, flattened) drawn once without transform:
// the single-level setting of accel-bench, whose hits have instance 0 and the world triangle index.
Scene flattened_single_mesh_scene(const Scene& scene);

}  // namespace glint::testing
