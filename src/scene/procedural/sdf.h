#pragma once
// Signed distance functions for the procedural creatures: ellipsoids and tapered capsules, blended
// with a polynomial smooth minimum. Negative inside, positive outside, roughly distance-scaled
// (the ellipsoid and the blend are bounds, not exact distances; the polygoniser only needs the
// sign and a value that is smooth and close to the distance near the surface).
#include "core/math.h"
#include "scene/procedural/implicit_field.h"

#include <cstdint>
#include <vector>

namespace glint::procedural {

// Polynomial smooth minimum: equals min(a, b) when |a - b| >= k, blends within k.
float smooth_min(float a, float b, float k);

struct SdfPrimitive {
  enum class Kind { ellipsoid, capsule };
  Kind kind = Kind::ellipsoid;
  // Ellipsoid: centre `a`, semi-axes `radii` along the columns of `axes` (a rotation).
  // Capsule: segment a -> b, radius ra at a and rb at b (linearly tapered).
  vec3 a{0.0f}, b{0.0f};
  vec3 radii{1.0f};
  glm::mat3 axes{1.0f};
  float ra = 0.0f, rb = 0.0f;
  // Armour bands: the surface is pushed out by up to `ridge_depth` in bands `ridge_period` apart
  // along `axes` column 0 (ellipsoids only; 0 = smooth).
  float ridge_depth = 0.0f, ridge_period = 1.0f;

  float distance(const vec3& p) const;
  // A sphere containing the primitive, for the early-out in BlendedShape: outside it,
  // distance(p) >= bound_scale() * (|p - bound_center()| - bound_radius()) - ridge_depth.
  vec3 bound_center() const;
  float bound_radius() const;
  float bound_scale() const;
};

SdfPrimitive ellipsoid(vec3 center, vec3 radii, const glm::mat3& axes = glm::mat3(1.0f));
SdfPrimitive capsule(vec3 a, vec3 b, float ra, float rb);

// The union of primitives blended by smooth_min with width `blend`, evaluated in order. A
// primitive whose distance is provably at least `blend` above the running result cannot change it
// (smooth_min then returns the running value exactly), so it is skipped: the result is identical
// to the full evaluation, only faster. For a ball of points (values_near) the primitives that
// cannot come within `blend` of the nearest one anywhere in the ball are dropped once, assuming
// each primitive's value changes at most twice as fast as a true distance.
class BlendedShape final : public ImplicitField {
public:
  BlendedShape() = default;
  explicit BlendedShape(float blend) : blend_(blend) {}
  void add(const SdfPrimitive& primitive);
  float distance(const vec3& p) const;
  float value(const vec3& p) const override { return distance(p); }
  void values_near(const vec3& centre, float radius, const vec3* points, float* out, std::size_t count) const override;
  vec3 gradient(const vec3& p, float step) const;  // central differences
  Aabb bounds() const;                              // contains every primitive's bounding sphere
  std::size_t size() const { return primitives_.size(); }

private:
  struct Entry {
    SdfPrimitive primitive;
    vec3 center;
    float radius;
    float scale;
  };
  // The running smooth union over `primitives_[order[0..count)]` with the per-point early-out.
  float fold(const vec3& p, const std::uint16_t* order, std::size_t count) const;
  std::vector<Entry> primitives_;
  std::vector<std::uint16_t> all_;  // 0, 1, ..., size - 1
  float blend_ = 0.05f;
};

}  // namespace glint::procedural
