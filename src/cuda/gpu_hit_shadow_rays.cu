#include "cuda/cuda_check.h"
#include "cuda/gpu_trace.h"
#include "rt/hit_shadow_ray.h"

namespace glint::cuda {
namespace {

constexpr unsigned int kBlock = 128;

// View: accel::TlasView or accel::KdTlasView (the hit triangle comes from the instance's mesh either way).
template <typename View>
__global__ void hit_shadow_rays_kernel(View tlas, const accel::Ray* rays, const accel::Hit* hits,
                                       const uint32_t* ray_count, uint32_t capacity, vec3 light, float origin_offset,
                                       accel::Ray* shadow_rays) {
  const uint32_t i = blockIdx.x * blockDim.x + threadIdx.x;
  const uint32_t count = ray_count != nullptr ? min(*ray_count, capacity) : capacity;
  if (i >= count) return;
  const accel::Hit hit = hits[i];
  if (!hit.valid()) {
    shadow_rays[i] = rt::empty_shadow_ray();
    return;
  }
  const accel::Instance& instance = tlas.instances[hit.instance];
  const accel::Triangle triangle = tlas.blases[instance.blas].mesh.triangle(hit.prim);
  const auto to_world = [&](vec3 p) { return vec3(instance.object_to_world * vec4(p, 1.0f)); };
  shadow_rays[i] = rt::hit_shadow_ray(rays[i], hit.u, hit.v, to_world(triangle.v0), to_world(triangle.v1),
                                      to_world(triangle.v2), light, origin_offset);
}

template <typename View>
void launch_kernel(const View& tlas, const accel::Ray* rays, const accel::Hit* hits, const uint32_t* ray_count,
                   uint32_t capacity, vec3 light, float origin_offset, accel::Ray* shadow_rays, cudaStream_t stream) {
  if (capacity == 0) return;
  const unsigned int blocks = (capacity + kBlock - 1) / kBlock;
  hit_shadow_rays_kernel<<<blocks, kBlock, 0, stream>>>(tlas, rays, hits, ray_count, capacity, light, origin_offset,
                                                         shadow_rays);
  GLINT_CUDA_CHECK(cudaGetLastError());
}

}  // namespace

void launch_hit_shadow_rays(const accel::TlasView& tlas, const accel::Ray* rays, const accel::Hit* hits,
                            const uint32_t* ray_count, uint32_t capacity, vec3 light, float origin_offset,
                            accel::Ray* shadow_rays, cudaStream_t stream) {
  launch_kernel(tlas, rays, hits, ray_count, capacity, light, origin_offset, shadow_rays, stream);
}

void launch_hit_shadow_rays(const accel::KdTlasView& tlas, const accel::Ray* rays, const accel::Hit* hits,
                            const uint32_t* ray_count, uint32_t capacity, vec3 light, float origin_offset,
                            accel::Ray* shadow_rays, cudaStream_t stream) {
  launch_kernel(tlas, rays, hits, ray_count, capacity, light, origin_offset, shadow_rays, stream);
}

}  // namespace glint::cuda
