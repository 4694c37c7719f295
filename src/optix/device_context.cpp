#include "optix/device_context.h"

#include "core/error.h"
#include "core/log.h"
#include "cuda/cuda_check.h"
#include "cuda/device_query.h"
#include "optix/result_check.h"

#include <cuda_runtime.h>
#include <optix.h>
// The OptiX function table lives in exactly one translation unit: this one.
#include <optix_function_table_definition.h>
#include <optix_stubs.h>

#include <cstdlib>
#include <cstring>
#include <mutex>
#include <string>

namespace glint::optix {
namespace {

std::string version_text(unsigned int version) {
  return fmt::format("{}.{}.{}", version / 10000, version % 10000 / 100, version % 100);
}

std::string cuda_driver_text() {
  int version = 0;
  if (cudaDriverGetVersion(&version) != cudaSuccess || version == 0) return "unknown";
  return fmt::format("{}.{}", version / 1000, version % 1000 / 10);
}

// What a user can do about each way optixInit fails.
std::string init_advice(OptixResult result) {
  switch (result) {
    case OPTIX_ERROR_LIBRARY_NOT_FOUND:
    case OPTIX_ERROR_ENTRY_SYMBOL_NOT_FOUND:
      return "the NVIDIA driver's OptiX runtime (libnvoptix.so.1) was not found; install the NVIDIA driver";
    case OPTIX_ERROR_UNSUPPORTED_ABI_VERSION:
    case OPTIX_ERROR_FUNCTION_TABLE_SIZE_MISMATCH:
      return fmt::format(
          "the driver's OptiX runtime (driver for CUDA {}) does not support the OptiX {} headers glint was built "
          "with (ABI {}); update the driver or rebuild glint with older OptiX headers (-DOptiX_INSTALL_DIR, e.g. "
          "OptiX 9.0 for driver 580)",
          cuda_driver_text(), version_text(OPTIX_VERSION), OPTIX_ABI_VERSION);
    default: return "see docs/optix.md";
  }
}

// optixInit loads the library and fills the process-wide function table: once, and its failure is
// remembered so that every later tracer reports the same line.
void initialise_optix_once() {
  static std::once_flag once;
  static OptixResult result = OPTIX_SUCCESS;
  std::call_once(once, [] { result = optixInit(); });
  if (result != OPTIX_SUCCESS)
    fail("the optix backend cannot start: optixInit failed with {}: {}", optix_result_name_before_init(result),
         init_advice(result));
}

void log_callback(unsigned int level, const char* tag, const char* message, void* /*cbdata*/) {
  if (level <= 2) {
    remember_optix_error_log(level, tag, message);
    log_debug("OptiX [{}] {}", tag, message);
  } else if (level == 3) {
    log_warning("OptiX [{}] {}", tag, message);
  } else {
    log_debug("OptiX [{}] {}", tag, message);
  }
}

bool validation_requested() {
#ifndef NDEBUG
  return true;
#else
  const char* value = std::getenv("GLINT_OPTIX_VALIDATION");
  return value != nullptr && std::strcmp(value, "1") == 0;
#endif
}

}  // namespace

DeviceContext::DeviceContext() {
  require_cuda_gpu("the optix backend");
  initialise_optix_once();
  // OptiX works in the current CUDA context; touching the runtime makes the primary one current.
  GLINT_CUDA_CHECK(cudaFree(nullptr));
  validation_ = validation_requested();
  OptixDeviceContextOptions options{};
  options.logCallbackFunction = &log_callback;
  options.logCallbackLevel = 4;  // everything; log_callback sorts it by level
  options.validationMode =
      validation_ ? OPTIX_DEVICE_CONTEXT_VALIDATION_MODE_ALL : OPTIX_DEVICE_CONTEXT_VALIDATION_MODE_OFF;
  GLINT_OPTIX_CHECK(optixDeviceContextCreate(nullptr, &options, &context_));
  if (validation_) log_info("OptiX {} validation mode on", version_text(OPTIX_VERSION));
}

DeviceContext::~DeviceContext() {
  if (context_) optixDeviceContextDestroy(context_);  // not checked: runs in a destructor
}

}  // namespace glint::optix
