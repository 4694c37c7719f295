// Watertight ray/triangle intersection, the formula of src/accel/intersect_triangle.h (Woop, Benthin,
// Wald, JCGT 2013) operation for operation, so the gl backend hits what the cpu backend hits up to
// the GPU's rounding of the two divisions. `precise` keeps the compiler from fusing or reordering
// the arithmetic: a shared edge must be evaluated with the same operations from both triangles, or
// rays could slip between them.

const float kInfinity = uintBitsToFloat(0x7F800000u);

// Per-ray precomputation: the dominant axis kz of the direction, the other two (swapped when
// direction[kz] < 0 to keep the winding), the origin's coordinates in that order, and the shear
// constants.
struct WatertightRay {
  ivec3 k;        // kx, ky, kz
  vec3 origin_k;  // origin[kx], origin[ky], origin[kz]
  float shear_x;
  float shear_y;
  float shear_z;
};

// v[k] by selects rather than a dynamic index, which a GPU compiler may turn into a trip through
// local memory; the same value either way.
float pick(vec3 v, int k) { return k == 0 ? v.x : (k == 1 ? v.y : v.z); }
vec3 pick(vec3 v, ivec3 k) { return vec3(pick(v, k.x), pick(v, k.y), pick(v, k.z)); }

WatertightRay make_watertight_ray(vec3 origin, vec3 direction) {
  WatertightRay ray;
  const vec3 magnitude = abs(direction);
  const int kz = magnitude.x > magnitude.y ? (magnitude.x > magnitude.z ? 0 : 2) : (magnitude.y > magnitude.z ? 1 : 2);
  int kx = kz == 2 ? 0 : kz + 1;
  int ky = kx == 2 ? 0 : kx + 1;
  if (pick(direction, kz) < 0.0) {
    const int swap = kx;
    kx = ky;
    ky = swap;
  }
  ray.k = ivec3(kx, ky, kz);
  ray.origin_k = pick(origin, ray.k);
  const vec3 direction_k = pick(direction, ray.k);
  precise float shear_x = direction_k.x / direction_k.z;
  precise float shear_y = direction_k.y / direction_k.z;
  precise float shear_z = 1.0 / direction_k.z;
  ray.shear_x = shear_x;
  ray.shear_y = shear_y;
  ray.shear_z = shear_z;
  return ray;
}

// True when the ray hits the triangle (either side) at t in [t_min, t_max]; then t, u, v (point =
// (1 - u - v) v0 + u v1 + v v2). The range test is made on the final t, as on the CPU.
bool intersect_triangle(WatertightRay ray, vec3 v0, vec3 v1, vec3 v2, float t_min, float t_max, out float t,
                        out float u, out float v) {
  // a = (v0 - origin) in the order kx, ky, kz: the same differences as the CPU's a[kx], a[ky], a[kz].
  precise vec3 a = pick(v0, ray.k) - ray.origin_k;
  precise vec3 b = pick(v1, ray.k) - ray.origin_k;
  precise vec3 c = pick(v2, ray.k) - ray.origin_k;
  precise float ax = a.x - ray.shear_x * a.z;
  precise float ay = a.y - ray.shear_y * a.z;
  precise float bx = b.x - ray.shear_x * b.z;
  precise float by = b.y - ray.shear_y * b.z;
  precise float cx = c.x - ray.shear_x * c.z;
  precise float cy = c.y - ray.shear_y * c.z;

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

  precise float az = ray.shear_z * a.z;
  precise float bz = ray.shear_z * b.z;
  precise float cz = ray.shear_z * c.z;
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
