// One libFuzzer program per target of fuzz_entries.h: CMake compiles this file once per target with
// GLINT_FUZZ_TARGET set to the target's name (cmake/GlintFuzz.cmake).
#include "core/error.h"
#include "core/log.h"
#include "fuzz_entries.h"

#include <tbb/global_control.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#ifndef GLINT_FUZZ_TARGET
#error "GLINT_FUZZ_TARGET names the fuzz target (obj_mtl, gltf, scene_json, texture)"
#endif

extern "C" int LLVMFuzzerInitialize(int* /*argc*/, char*** /*argv*/) {
  // Warnings about bad inputs are expected by the million; printing them would only slow the run.
  glint::set_log_level(glint::LogLevel::error);
  // One thread per fuzzing process: the loaders' BVH (the default walkthrough's probe) is tiny, and
  // run_fuzzers.sh runs one process per core already.
  static tbb::global_control one_thread(tbb::global_control::max_allowed_parallelism, 1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const glint::fuzz::FuzzTarget* const target = glint::fuzz::find_fuzz_target(GLINT_FUZZ_TARGET);
  if (target == nullptr) {
    std::fprintf(stderr, "no fuzz target named %s\n", GLINT_FUZZ_TARGET);
    std::abort();
  }
  try {
    target->entry({data, size});
  } catch (const glint::Error&) {
    // The loader rejected the input with a message: a correct outcome. Any other exception escapes,
    // terminates the program and libFuzzer keeps the input as a crash.
  }
  return 0;
}
