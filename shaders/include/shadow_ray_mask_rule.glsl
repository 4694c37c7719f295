// What a pixel's shadow ray says about its shadow mask (RayTracedShadows, docs/render.md "Shadow
// methods"), the one rule of both ways the mask is made: shadow_ray_mask.comp.glsl from a traced ray
// list, shadow_rays_inline.comp.glsl from the ray it traces itself (gl backend). A pixel that needs no
// ray gets an empty one (t_max = 0 < t_min, which every backend's any-hit rejects at once) whose t_min
// says the pixel's value (pixel_shadow_ray.glsl decides):
#include "include/accel_records.glsl"

const float kShadowRayKeep = 1.0;        // hybrid: the cube's value is certain: kept
const float kShadowRayUnlit = 2.0;       // facing away from the light: 0, unlit whatever the shadow says
const float kShadowRayBackground = 3.0;  // background: 1, as the cube's mask

Ray empty_pixel_shadow_ray(float code) { return Ray(vec3(0.0), code, vec3(0.0, 0.0, 1.0), 0.0); }

// The mask at a pixel whose shadow ray is `ray`: 0 where it was occluded (`occluded`, the ray's
// answer, which only a cast ray has), 1 where not, an empty ray's value by its t_min; false where the
// mask keeps the value it has (hybrid: the cube's).
bool shadow_ray_mask_value(Ray ray, bool occluded, out float value) {
  value = 0.0;
  if (!is_empty(ray)) {
    value = occluded ? 0.0 : 1.0;
    return true;
  }
  if (ray.t_min == kShadowRayUnlit) return true;
  value = 1.0;
  return ray.t_min == kShadowRayBackground;
}
