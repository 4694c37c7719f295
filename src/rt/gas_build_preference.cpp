#include "rt/gas_build_preference.h"

#include "core/error.h"

namespace glint::rt {

std::string_view optix_accel_name(OptixBuildPreference preference) {
  switch (preference) {
    case OptixBuildPreference::fast_trace: return "optix-fasttrace";
    case OptixBuildPreference::fast_build: return "optix-fastbuild";
  }
  return "?";
}

bool is_optix_accel_name(std::string_view name) {
  for (const OptixBuildPreference preference : kAllOptixBuildPreferences)
    if (optix_accel_name(preference) == name) return true;
  return false;
}

OptixBuildPreference parse_optix_accel(std::string_view name) {
  for (const OptixBuildPreference preference : kAllOptixBuildPreferences)
    if (optix_accel_name(preference) == name) return preference;
  fail("unknown OptiX structure \"{}\" (known: optix-fasttrace, optix-fastbuild)", name);
}

}  // namespace glint::rt
