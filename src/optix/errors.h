#pragma once
// How OptiX failures become glint::Error. The context's log callback (device_context.cpp)
// records OptiX's error-level messages here, and the next failed call's error carries them, so the
// one line the CLI prints says what OptiX complained about. Needs the OptiX headers.
#include <optix_types.h>

#include <string>
#include <string_view>

namespace glint::optix {

// "OptiX error <name> (<text>) in <call> at <file>:<line>[: <OptiX's log>]"; used by GLINT_OPTIX_CHECK.
[[noreturn]] void throw_optix_error(OptixResult result, const char* call, const char* file, int line,
                                    std::string_view compile_log = {});

// Keeps an error-level message of OptiX's log (level 1 fatal, 2 error) for the next thrown error.
void remember_optix_error_log(unsigned int level, const char* tag, const char* message);

// The name of an OptixResult without the function table (optixGetErrorName needs a successful
// optixInit): for optixInit's own failures.
std::string optix_result_name_before_init(OptixResult result);

}  // namespace glint::optix
