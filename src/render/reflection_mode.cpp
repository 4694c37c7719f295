#include "render/reflection_mode.h"

#include "core/error.h"

#include <string>

namespace glint::render {

std::string_view reflection_mode_name(ReflectionMode mode) {
  switch (mode) {
    case ReflectionMode::off: return "off";
    case ReflectionMode::ssr: return "ssr";
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

}  // namespace glint::render
