#pragma once
// The sine deformer's per-vertex and per-triangle formulas, shared by the CPU deformer
// (sine_deformer.cpp) and the CUDA one (cuda/gpu_sine_deformer.cu), so both pose a mesh the same way.
#include "core/math.h"
#include "scene/scene.h"

#include <cmath>

namespace glint {

// std:: maths on the host (bit-identical to the CPU deformer of earlier versions), CUDA's on the device.
GLINT_HOST_DEVICE inline float deform_sin(float x) {
#if defined(__CUDA_ARCH__)
  return sinf(x);
#else
  return std::sin(x);
#endif
}

GLINT_HOST_DEVICE inline bool deform_isfinite(float x) {
#if defined(__CUDA_ARCH__)
  return isfinite(x);
#else
  return std::isfinite(x);
#endif
}

// The rest position moved along displace_axis by amplitude * sin(frequency * rest[wave_axis] + phase),
// phase = speed * time.
GLINT_HOST_DEVICE inline vec3 sine_displaced(const vec3& rest, const SineDeform& p, float phase) {
  vec3 moved = rest;
  moved[p.displace_axis] = rest[p.displace_axis] + p.amplitude * deform_sin(p.frequency * rest[p.wave_axis] + phase);
  return moved;
}

// Unnormalised face normal: its length is twice the area, the weight of an area-weighted smooth normal.
GLINT_HOST_DEVICE inline vec3 weighted_face_normal(const vec3& a, const vec3& b, const vec3& c) {
  return glm::cross(b - a, c - a);
}

// The smooth normal from the sum of a vertex's weighted face normals: +y where it vanishes.
GLINT_HOST_DEVICE inline vec3 smooth_normal_from_sum(const vec3& sum) {
  const float length = glm::length(sum);
  return (length > 0.0f && deform_isfinite(length)) ? sum / length : vec3(0.0f, 1.0f, 0.0f);
}

}  // namespace glint
