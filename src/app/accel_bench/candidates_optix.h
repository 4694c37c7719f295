#pragma once
// accel-bench's optix rows (`accel-bench --backend optix`): one OptiX GAS over the scene's world
// triangles per OptiX build preference, traced with the optix backend's device programs, in the
// same Candidate interface as glint's own structures, so their hits are checked against the
// reference and their build, refit and trace times land in the same table.
#include "app/accel_bench/candidates.h"

#include <string>
#include <vector>

namespace glint::accel_bench {

// "optix-fasttrace", "optix-fastbuild" (known in every build, for validating command lines).
std::vector<std::string> optix_candidate_names();

// True when this build has the optix backend (GLINT_HAVE_OPTIX).
bool optix_candidates_built();

// One entry per optix_candidate_names() name. Making a candidate creates an OptiX context: glint::Error
// (one line) without a CUDA GPU or a usable OptiX driver. In a build without OptiX making one throws
// the line saying how to enable it (backends::check_backend_built).
std::vector<CandidateEntry> optix_candidate_menu();

}  // namespace glint::accel_bench
