#pragma once
// One OptiX device context on the current CUDA device, with OptiX's log routed into glint's (errors
// into the next glint::Error, warnings to log_warning, the rest to log_debug) and validation mode on
// in debug builds or when the environment variable GLINT_OPTIX_VALIDATION=1. Needs the OptiX headers.
#include <optix_types.h>

namespace glint::optix {

class DeviceContext {
public:
  // Loads OptiX from the driver once per process (optixInit). glint::Error, one line, when there is
  // no CUDA GPU, no OptiX in the driver, or the driver's OptiX does not support the headers glint
  // was built with (the line names optixInit's error and both versions).
  DeviceContext();
  ~DeviceContext();
  DeviceContext(const DeviceContext&) = delete;
  DeviceContext& operator=(const DeviceContext&) = delete;

  OptixDeviceContext get() const { return context_; }
  bool validation() const { return validation_; }

private:
  OptixDeviceContext context_ = nullptr;
  bool validation_ = false;
};

}  // namespace glint::optix
