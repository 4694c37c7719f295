#pragma once
// Where a `glint bench` run was measured, for summary.json and report.md: the GL renderer and its
// version string (which carries the driver version on NVIDIA and Mesa), the CUDA devices and driver,
// glint's version and the git commit of the source it was built from (when the executable sits in a
// git work tree, as a build folder does; absent otherwise).
#include "gl/egl_context.h"

#include <nlohmann/json.hpp>

namespace glint::bench {

// {"glint_version", "git_commit" (or null), "git_dirty", "gl": {renderer, vendor, version,
//  pass_timing}, "cuda_devices": [{name, compute_capability, memory_bytes, driver_version}],
//  "cuda_note" (why there are none)}
nlohmann::json describe_environment(const HeadlessGlContext& context);

}  // namespace glint::bench
