#include "scene/procedural/sdf.h"

#include "core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint::procedural {

float smooth_min(float a, float b, float k) {
  const float h = std::max(k - std::abs(a - b), 0.0f) / k;
  return std::min(a, b) - h * h * k * 0.25f;
}

float SdfPrimitive::distance(const vec3& p) const {
  if (kind == Kind::capsule) {
    const vec3 ab = b - a, ap = p - a;
    const float h = std::clamp(glm::dot(ap, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(ap - h * ab) - (ra + (rb - ra) * h);
  }
  // Ellipsoid distance bound: scale the sphere distance by the local stretch,
  // d ~ k0 (k0 - 1) / k1 with k0 = |q / r|, k1 = |q / r^2| (exact on the surface's gradient
  // direction, slightly conservative away from it).
  const vec3 q = glm::transpose(axes) * (p - a);
  const float k0 = glm::length(q / radii);
  const float k1 = glm::length(q / (radii * radii));
  float d = k1 > 1e-12f ? k0 * (k0 - 1.0f) / k1 : -std::min(radii.x, std::min(radii.y, radii.z));
  if (ridge_depth > 0.0f) {
    // Raised bands across the first axis, strongest on the upper half (the back's armour plates).
    const float band = 0.5f + 0.5f * std::cos(6.28318530718f * q.x / ridge_period);
    d -= ridge_depth * band * band;
  }
  return d;
}

vec3 SdfPrimitive::bound_center() const { return kind == Kind::capsule ? 0.5f * (a + b) : a; }

float SdfPrimitive::bound_radius() const {
  if (kind == Kind::capsule) return 0.5f * glm::length(b - a) + std::max(ra, rb);
  return std::max(radii.x, std::max(radii.y, radii.z));
}

float SdfPrimitive::bound_scale() const {
  // The capsule's value is at least the distance to its segment minus the larger radius. For the
  // ellipsoid, outside the sphere of radius r_max: k0 >= |q| / r_max >= 1 and k1 <= |q| / r_min^2,
  // so k0 (k0 - 1) / k1 >= (r_min / r_max)^2 (|q| - r_max).
  if (kind == Kind::capsule) return 1.0f;
  const float lo = std::min(radii.x, std::min(radii.y, radii.z)), hi = std::max(radii.x, std::max(radii.y, radii.z));
  return (lo / hi) * (lo / hi);
}

SdfPrimitive ellipsoid(vec3 center, vec3 radii, const glm::mat3& axes) {
  SdfPrimitive p;
  p.kind = SdfPrimitive::Kind::ellipsoid;
  p.a = center;
  p.radii = radii;
  p.axes = axes;
  return p;
}

SdfPrimitive capsule(vec3 a, vec3 b, float ra, float rb) {
  SdfPrimitive p;
  p.kind = SdfPrimitive::Kind::capsule;
  p.a = a;
  p.b = b;
  p.ra = ra;
  p.rb = rb;
  return p;
}

void BlendedShape::add(const SdfPrimitive& primitive) {
  if (primitives_.size() >= 65535) fail("BlendedShape: too many primitives");
  all_.push_back(static_cast<std::uint16_t>(primitives_.size()));
  primitives_.push_back({primitive, primitive.bound_center(), primitive.bound_radius(), primitive.bound_scale()});
}

float BlendedShape::fold(const vec3& p, const std::uint16_t* order, std::size_t count) const {
  float result = std::numeric_limits<float>::max();
  for (std::size_t n = 0; n < count; ++n) {
    const Entry& e = primitives_[order[n]];
    // A lower bound of the primitive's value (SdfPrimitive::bound_scale); when even that is
    // `blend` above the running result, smooth_min would return the running result unchanged.
    const float outside = glm::length(p - e.center) - e.radius;
    if (outside >= 0.0f && e.scale * outside - e.primitive.ridge_depth >= result + blend_) continue;
    const float d = e.primitive.distance(p);
    result = result == std::numeric_limits<float>::max() ? d : smooth_min(result, d, blend_);
  }
  return result;
}

float BlendedShape::distance(const vec3& p) const {
  return fold(p, all_.data(), all_.size());
}

void BlendedShape::values_near(const vec3& centre, float radius, const vec3* points, float* out,
                               std::size_t count) const {
  constexpr float kLipschitz = 2.0f;
  // Every point of the ball has a primitive within `nearest` (the smallest upper bound).
  float nearest = std::numeric_limits<float>::max();
  for (const Entry& e : primitives_) nearest = std::min(nearest, e.primitive.distance(centre) + kLipschitz * radius);
  std::vector<std::uint16_t> kept;
  kept.reserve(primitives_.size());
  for (std::size_t i = 0; i < primitives_.size(); ++i) {
    const Entry& e = primitives_[i];
    const float outside = glm::length(centre - e.center) - e.radius - radius;
    if (outside >= 0.0f && e.scale * outside - e.primitive.ridge_depth >= nearest + blend_) continue;
    kept.push_back(static_cast<std::uint16_t>(i));
  }
  for (std::size_t q = 0; q < count; ++q) out[q] = fold(points[q], kept.data(), kept.size());
}

vec3 BlendedShape::gradient(const vec3& p, float step) const {
  const vec3 dx(step, 0, 0), dy(0, step, 0), dz(0, 0, step);
  return vec3(distance(p + dx) - distance(p - dx), distance(p + dy) - distance(p - dy),
              distance(p + dz) - distance(p - dz)) /
         (2.0f * step);
}

Aabb BlendedShape::bounds() const {
  Aabb box;
  for (const Entry& e : primitives_) {
    box.extend(e.center - vec3(e.radius));
    box.extend(e.center + vec3(e.radius));
  }
  return box;
}

}  // namespace glint::procedural
