// accel::Ray (32 bytes) and accel::Hit (20 bytes) as std430 structs: the records the gl backend's walk
// reads and writes, and the dense shadow-ray rule (pixel_shadow_ray.glsl) makes. One definition, so a shader that both makes a ray and walks it (a pass that traces inline) declares
// each struct once.
struct Ray {
  vec3 origin;
  float t_min;
  vec3 direction;
  float t_max;
};

// An empty ray (t_min > t_max) stands for no ray at all: every backend rejects it at once, never
// occluded, never hit.
bool is_empty(Ray ray) { return ray.t_min > ray.t_max; }

struct Hit {
  float t;
  uint instance;
  uint prim;
  float u;
  float v;
};
