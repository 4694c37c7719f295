#pragma once
// Watertight ray/triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013). The ray is sheared so that it runs along +z from the origin; the
// triangle's 2D edge functions are then evaluated in that space. Neighbouring triangles evaluate a
// shared edge with exactly the same operations on the same operands, so a ray through an edge or
// a vertex can never slip between them. Edge values that come out exactly 0 are recomputed in
// double, where the products of floats are exact, so their sign is right.
#include "accel/ray.h"
#include "accel/triangle_mesh.h"

namespace glint::accel {

// Per-ray precomputation: the dominant axis kz of the direction, the other two (swapped when
// direction[kz] < 0 to keep the winding), and the shear constants.
struct WatertightRay {
  vec3 origin;
  int kx, ky, kz;
  float shear_x, shear_y, shear_z;
};

GLINT_HOST_DEVICE inline WatertightRay make_watertight_ray(const vec3& origin, const vec3& direction) {
  WatertightRay ray;
  ray.origin = origin;
  const vec3 magnitude(direction.x < 0 ? -direction.x : direction.x, direction.y < 0 ? -direction.y : direction.y,
                       direction.z < 0 ? -direction.z : direction.z);
  ray.kz = magnitude.x > magnitude.y ? (magnitude.x > magnitude.z ? 0 : 2) : (magnitude.y > magnitude.z ? 1 : 2);
  ray.kx = ray.kz == 2 ? 0 : ray.kz + 1;
  ray.ky = ray.kx == 2 ? 0 : ray.kx + 1;
  if (direction[ray.kz] < 0.0f) {
    const int swap = ray.kx;
    ray.kx = ray.ky;
    ray.ky = swap;
  }
  ray.shear_x = direction[ray.kx] / direction[ray.kz];
  ray.shear_y = direction[ray.ky] / direction[ray.kz];
  ray.shear_z = 1.0f / direction[ray.kz];
  return ray;
}

// A vector's components in the ray's axis order: v[kx], v[ky], v[kz].
struct AxisOrdered {
  float x, y, z;
};

GLINT_HOST_DEVICE inline AxisOrdered in_ray_axes(const WatertightRay& ray, const vec3& v) {
#if defined(__CUDA_ARCH__)
  // Selects: indexing a local array with the per-ray axes puts the array in local memory on the
  // GPU, a store and three loads per vertex; in the closest-hit kernel that was most of its local
  // memory traffic (docs/perf.md, "Tenth round").
  const auto pick = [&v](int axis) { return axis == 0 ? v.x : (axis == 1 ? v.y : v.z); };
  return {pick(ray.kx), pick(ray.ky), pick(ray.kz)};
#else
  // On the CPU an index into a plain array is a load, where glm's operator[] is a switch.
  const float c[3] = {v.x, v.y, v.z};
  return {c[ray.kx], c[ray.ky], c[ray.kz]};
#endif
}

struct TriangleHit {
  float t, u, v;  // point = (1 - u - v) * v0 + u * v1 + v * v2
};

// True when the ray hits the triangle (either side) at t in [t_min, t_max]. The range test is made
// on the final t, so a given ray/triangle pair always yields the same t whatever t_max is: a BVH
// traversal and a brute-force loop agree bit for bit on the closest t.
GLINT_HOST_DEVICE inline bool intersect_triangle(const WatertightRay& ray, const Triangle& tri, float t_min, float t_max,
                                                 TriangleHit& hit) {
  const AxisOrdered a = in_ray_axes(ray, tri.v0 - ray.origin);
  const AxisOrdered b = in_ray_axes(ray, tri.v1 - ray.origin);
  const AxisOrdered c = in_ray_axes(ray, tri.v2 - ray.origin);
  const float ax = a.x - ray.shear_x * a.z;
  const float ay = a.y - ray.shear_y * a.z;
  const float bx = b.x - ray.shear_x * b.z;
  const float by = b.y - ray.shear_y * b.z;
  const float cx = c.x - ray.shear_x * c.z;
  const float cy = c.y - ray.shear_y * c.z;

  // Scaled barycentrics: e0 weighs v0, e1 weighs v1, e2 weighs v2.
  float e0 = cx * by - cy * bx;
  float e1 = ax * cy - ay * cx;
  float e2 = bx * ay - by * ax;
  if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
    e0 = static_cast<float>(static_cast<double>(cx) * by - static_cast<double>(cy) * bx);
    e1 = static_cast<float>(static_cast<double>(ax) * cy - static_cast<double>(ay) * cx);
    e2 = static_cast<float>(static_cast<double>(bx) * ay - static_cast<double>(by) * ax);
  }
  if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
  const float det = e0 + e1 + e2;
  if (det == 0.0f) return false;  // ray in the triangle's plane, or a degenerate triangle

  const float az = ray.shear_z * a.z;
  const float bz = ray.shear_z * b.z;
  const float cz = ray.shear_z * c.z;
  const float scaled_t = e0 * az + e1 * bz + e2 * cz;
  const float inv_det = 1.0f / det;
  const float t = scaled_t * inv_det;
  // Written so that NaN (degenerate ray) fails, and an overflow to infinity is no hit.
  if (!(t >= t_min && t <= t_max && t < kInfinity)) return false;
  hit.t = t;
  hit.u = e1 * inv_det;
  hit.v = e2 * inv_det;
  return true;
}

}  // namespace glint::accel
