#include "render/reflection_mode.h"

#include "core/error.h"

#include <string>

namespace glint::render {

std::string_view reflection_mode_name(ReflectionMode mode) {
  switch (mode) {
    case ReflectionMode::off: return "off";
    case ReflectionMode::ssr: return "ssr";
    case ReflectionMode::hybrid: return "hybrid";
    case ReflectionMode::rt: return "rt";
  }
  return "?";
}

ReflectionMode parse_reflection_mode(std::string_view name) {
  std::string known;
  for (const ReflectionMode mode : kAllReflectionModes) {
    if (reflection_mode_name(mode) == name) return mode;
    if (!known.empty()) known += ", ";
    known += reflection_mode_name(mode);
  }
  fail("unknown reflection mode '{}' (known: {})", name, known);
}

bool uses_ssr(ReflectionMode mode) { return mode == ReflectionMode::ssr || mode == ReflectionMode::hybrid; }

bool uses_ray_tracing(ReflectionMode mode) { return mode == ReflectionMode::hybrid || mode == ReflectionMode::rt; }

}  // namespace glint::render
