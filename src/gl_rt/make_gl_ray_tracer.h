#pragma once
// The gl backend's factory, declared without GL so that backends/registry.cpp (make_ray_tracer("gl"))
// stays free of GL headers.
#include "rt/ray_tracer.h"

#include <memory>

namespace glint::gl_rt {

// A GlRayTracer (gl_ray_tracer.h) on the OpenGL context current on this thread; glint::Error
// ("--backend gl needs an OpenGL 4.5 context: ...") when none is, or it is older than 4.5.
std::unique_ptr<rt::RayTracer> make_gl_ray_tracer();

}  // namespace glint::gl_rt
