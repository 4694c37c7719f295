#pragma once
// The current time as ISO 8601 UTC ("2026-11-23T15:50:12Z"), the date every run record and report
// carries.
#include <string>

namespace glint {

std::string utc_timestamp();

}  // namespace glint
