#pragma once
// Whether a ray tracing backend can run on this machine with this build, and if not, why: the
// reason `glint bench` reports for the cells it skips. Read from the backend registry
// (backends/registry.h), so a backend added there, or registered by a test, is picked up without a
// change here: one this binary lacks says why; one on a CUDA GPU (cuda, optix) needs a CUDA GPU. None
// is made here: gl needs the OpenGL 4.5 context every cell renders with, which does not exist yet.
#include <optional>
#include <string>

namespace glint::bench {

// nullopt when `backend` can run here; otherwise one line saying why not. glint::Error for a name
// the registry does not know.
std::optional<std::string> backend_unavailable_reason(const std::string& backend);

}  // namespace glint::bench
