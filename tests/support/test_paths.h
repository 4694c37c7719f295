#pragma once
// Where the tests find the source tree and the glint executable. Both default to the build's own
// paths; GLINT_SOURCE_DIR and GLINT_CLI in the environment override them, so the test binary can run
// from a bundle on another machine (the GPU machine) against its checkout there.
#include <cstdlib>
#include <filesystem>
#include <string>

namespace glint::testing {

inline std::filesystem::path source_dir() {
  const char* env = std::getenv("GLINT_SOURCE_DIR");
  return (env != nullptr && *env != '\0') ? std::filesystem::path(env) : std::filesystem::path(GLINT_SOURCE_DIR);
}

inline std::string cli_path() {
  const char* env = std::getenv("GLINT_CLI");
  return (env != nullptr && *env != '\0') ? std::string(env) : std::string(GLINT_CLI_PATH);
}

}  // namespace glint::testing
