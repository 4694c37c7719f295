#include "render/reflection_mode.h"

namespace glint::render {

bool uses_ssr(ReflectionMode mode) {
  return mode == ReflectionMode::ssr || mode == ReflectionMode::hybrid || mode == ReflectionMode::adaptive;
}

bool uses_ray_tracing(ReflectionMode mode) {
  return mode == ReflectionMode::hybrid || mode == ReflectionMode::rt || mode == ReflectionMode::adaptive;
}

}  // namespace glint::render
