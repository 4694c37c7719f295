#pragma once
// The interface between implicit shapes (scene/procedural/sdf.h) and the polygoniser
// (scene/procedural/isosurface.h): a signed scalar field, negative inside.
#include "core/math.h"

#include <cstddef>
#include <functional>
#include <utility>

namespace glint::procedural {

// The field to polygonise. Must be pure (same input, same output) and thread-safe.
class ImplicitField {
public:
  virtual ~ImplicitField() = default;
  virtual float value(const vec3& p) const = 0;
  // Values at `count` points, all within `radius` of `centre`. The default calls value(); a field
  // made of parts overrides it to find the parts that matter for the ball once (BlendedShape).
  virtual void values_near(const vec3& centre, float radius, const vec3* points, float* out, std::size_t count) const;
};

// A plain function as a field.
using ScalarField = std::function<float(const vec3&)>;
class FunctionField final : public ImplicitField {
public:
  explicit FunctionField(ScalarField function) : function_(std::move(function)) {}
  float value(const vec3& p) const override { return function_(p); }

private:
  ScalarField function_;
};

}  // namespace glint::procedural
