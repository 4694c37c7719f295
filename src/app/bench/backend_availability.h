#pragma once
// Whether a ray tracing backend can run on this machine with this build, and if not, why: the
// reason `glint bench` reports for the cells it skips. GPU backends (cuda, optix) need a CUDA GPU;
// every backend must be known to rt::make_ray_tracer (cuda and optix join it as they are built), so
// a backend that lands later is picked up without a change here. gl needs only the OpenGL 4.5
// context every cell renders with, so it is not made here, before that context exists.
#include <optional>
#include <string>

namespace glint::bench {

// The backends `glint bench --backends` accepts.
inline constexpr const char* kBenchBackends[] = {"cpu", "embree", "cuda", "optix", "gl"};

// nullopt when `backend` can run here; otherwise one line saying why not.
std::optional<std::string> backend_unavailable_reason(const std::string& backend);

}  // namespace glint::bench
