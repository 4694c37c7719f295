#pragma once
// Every OptiX call goes through GLINT_OPTIX_CHECK, so a failure becomes one glint::Error naming the
// call, the OptiX error, the file and line, and what OptiX logged about it. Needs the OptiX headers.
#include "optix/errors.h"

#include <optix.h>

#define GLINT_OPTIX_CHECK(call)                                                              \
  do {                                                                                       \
    const OptixResult glint_optix_result_ = (call);                                          \
    if (glint_optix_result_ != OPTIX_SUCCESS)                                                \
      ::glint::optix::throw_optix_error(glint_optix_result_, #call, __FILE__, __LINE__);     \
  } while (0)

// For the calls that also write a log string (module and pipeline creation): its text is added to
// the error. `log` is a char array, `log_size` a size_t variable holding its size before the call.
#define GLINT_OPTIX_CHECK_LOG(call, log, log_size)                                                                   \
  do {                                                                                                               \
    const OptixResult glint_optix_result_ = (call);                                                                  \
    if (glint_optix_result_ != OPTIX_SUCCESS)                                                                        \
      ::glint::optix::throw_optix_error(glint_optix_result_, #call, __FILE__, __LINE__,                              \
                                        std::string_view(log, log_size > sizeof(log) ? sizeof(log) : log_size));     \
  } while (0)
