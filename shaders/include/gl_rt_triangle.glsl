// Watertight ray/triangle intersection, the formula of src/accel/intersect_triangle.h (Woop, Benthin,
// Wald, JCGT 2013) operation for operation, so the gl backend hits what the cpu backend hits up to
// the GPU's rounding of the two divisions. `precise` keeps the compiler from fusing or reordering
// the arithmetic: a shared edge must be evaluated with the same operations from both triangles, or
// rays could slip between them.

const float kInfinity = uintBitsToFloat(0x7F800000u);

// Per-ray precomputation: the dominant axis kz of the direction, the other two (swapped when
// direction[kz] < 0 to keep the winding), and the shear constants.
struct WatertightRay {
  vec3 origin;
  int kx;
  int ky;
  int kz;
  float shear_x;
  float shear_y;
  float shear_z;
};

WatertightRay make_watertight_ray(vec3 origin, vec3 direction) {
  WatertightRay ray;
  ray.origin = origin;
  const vec3 magnitude = abs(direction);
  ray.kz = magnitude.x > magnitude.y ? (magnitude.x > magnitude.z ? 0 : 2) : (magnitude.y > magnitude.z ? 1 : 2);
  ray.kx = ray.kz == 2 ? 0 : ray.kz + 1;
  ray.ky = ray.kx == 2 ? 0 : ray.kx + 1;
  if (direction[ray.kz] < 0.0) {
    const int swap = ray.kx;
    ray.kx = ray.ky;
    ray.ky = swap;
  }
  precise float shear_x = direction[ray.kx] / direction[ray.kz];
  precise float shear_y = direction[ray.ky] / direction[ray.kz];
  precise float shear_z = 1.0 / direction[ray.kz];
  ray.shear_x = shear_x;
  ray.shear_y = shear_y;
  ray.shear_z = shear_z;
  return ray;
}

// True when the ray hits the triangle (either side) at t in [t_min, t_max]; then t, u, v (point =
// (1 - u - v) v0 + u v1 + v v2). The range test is made on the final t, as on the CPU.
bool intersect_triangle(WatertightRay ray, vec3 v0, vec3 v1, vec3 v2, float t_min, float t_max, out float t,
                        out float u, out float v) {
  precise vec3 a = v0 - ray.origin;
  precise vec3 b = v1 - ray.origin;
  precise vec3 c = v2 - ray.origin;
  precise float ax = a[ray.kx] - ray.shear_x * a[ray.kz];
  precise float ay = a[ray.ky] - ray.shear_y * a[ray.kz];
  precise float bx = b[ray.kx] - ray.shear_x * b[ray.kz];
  precise float by = b[ray.ky] - ray.shear_y * b[ray.kz];
  precise float cx = c[ray.kx] - ray.shear_x * c[ray.kz];
  precise float cy = c[ray.ky] - ray.shear_y * c[ray.kz];

  // Scaled barycentrics: e0 weighs v0, e1 weighs v1, e2 weighs v2. Exactly 0: recomputed in double,
  // where the products of floats are exact, so the sign is right.
  precise float e0 = cx * by - cy * bx;
  precise float e1 = ax * cy - ay * cx;
  precise float e2 = bx * ay - by * ax;
  if (e0 == 0.0 || e1 == 0.0 || e2 == 0.0) {
    e0 = float(double(cx) * double(by) - double(cy) * double(bx));
    e1 = float(double(ax) * double(cy) - double(ay) * double(cx));
    e2 = float(double(bx) * double(ay) - double(by) * double(ax));
  }
  t = kInfinity;
  u = 0.0;
  v = 0.0;
  if ((e0 < 0.0 || e1 < 0.0 || e2 < 0.0) && (e0 > 0.0 || e1 > 0.0 || e2 > 0.0)) return false;
  precise float det = e0 + e1 + e2;
  if (det == 0.0) return false;  // ray in the triangle's plane, or a degenerate triangle

  precise float az = ray.shear_z * a[ray.kz];
  precise float bz = ray.shear_z * b[ray.kz];
  precise float cz = ray.shear_z * c[ray.kz];
  precise float scaled_t = e0 * az + e1 * bz + e2 * cz;
  precise float inv_det = 1.0 / det;
  precise float hit_t = scaled_t * inv_det;
  // Written so that NaN (degenerate ray) fails, and an overflow to infinity is no hit.
  if (!(hit_t >= t_min && hit_t <= t_max && hit_t < kInfinity)) return false;
  precise float hit_u = e1 * inv_det;
  precise float hit_v = e2 * inv_det;
  t = hit_t;
  u = hit_u;
  v = hit_v;
  return true;
}
