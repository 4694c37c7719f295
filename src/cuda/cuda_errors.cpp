// Host-side bodies of cuda_check.h's throwers (plain C++: no CUDA headers needed).
#include "cuda/cuda_errors.h"

#include "core/error.h"

#include <cstring>
#include <string>

namespace glint::cuda {

void throw_cuda_error(const char* error_name, const char* error_text, const char* call, const char* file, int line) {
  // Only the file's name: the build directory's absolute path says nothing to a user.
  const char* slash = std::strrchr(file, '/');
  fail("CUDA error {} ({}) in {} at {}:{}", error_name, error_text, call, slash ? slash + 1 : file, line);
}

void fail_message(const std::string& message) { throw Error(message); }

}  // namespace glint::cuda
