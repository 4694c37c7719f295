#pragma once
// How CUDA code reports failures as glint::Error. Plain C++ (no CUDA headers): the bodies live in
// cuda_errors.cpp because .cu files never format with fmt (nvcc's front end cannot evaluate fmt 9's
// C++20 consteval format-string check).
#include <string>

namespace glint::cuda {

// "CUDA error <name> (<text>) in <call> at <file>:<line>"; used by GLINT_CUDA_CHECK.
[[noreturn]] void throw_cuda_error(const char* error_name, const char* error_text, const char* call, const char* file,
                                   int line);
// Throws glint::Error(message): the way .cu files report a bad argument.
[[noreturn]] void fail_message(const std::string& message);

}  // namespace glint::cuda
