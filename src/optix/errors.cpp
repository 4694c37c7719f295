#include "optix/errors.h"

#include "core/error.h"

#include <optix.h>
#include <optix_stubs.h>

#include <cstring>
#include <mutex>
#include <string>

namespace glint::optix {
namespace {

// OptiX reports errors through return codes and, in more words, through the log callback, which
// runs on the calling thread before the call returns; the messages wait here until the failing
// call's error takes them. Bounded: a long validation report is cut.
constexpr std::size_t kMaxRememberedLog = 2000;
std::mutex remembered_mutex;
std::string remembered_log;

std::string take_remembered_log() {
  const std::lock_guard lock(remembered_mutex);
  std::string log;
  log.swap(remembered_log);
  return log;
}

std::string_view trimmed(std::string_view text) {
  text = text.substr(0, text.find('\0'));
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.remove_suffix(1);
  return text;
}

}  // namespace

void remember_optix_error_log(unsigned int level, const char* tag, const char* message) {
  const std::lock_guard lock(remembered_mutex);
  if (remembered_log.size() >= kMaxRememberedLog) return;
  if (!remembered_log.empty()) remembered_log += "; ";
  remembered_log += fmt::format("[{}][{}] {}", level == 1 ? "fatal" : "error", tag, trimmed(message));
  if (remembered_log.size() > kMaxRememberedLog) remembered_log.resize(kMaxRememberedLog);
}

void throw_optix_error(OptixResult result, const char* call, const char* file, int line, std::string_view compile_log) {
  // Only the file's name: the build directory's absolute path says nothing to a user.
  const char* slash = std::strrchr(file, '/');
  std::string details = take_remembered_log();
  const std::string_view compile = trimmed(compile_log);
  if (!compile.empty()) details += fmt::format("{}{}", details.empty() ? "" : "; ", compile);
  fail("OptiX error {} ({}) in {} at {}:{}{}{}", optixGetErrorName(result), optixGetErrorString(result), call,
       slash ? slash + 1 : file, line, details.empty() ? "" : ": ", details);
}

std::string optix_result_name_before_init(OptixResult result) {
  switch (result) {
    case OPTIX_SUCCESS: return "OPTIX_SUCCESS";
    case OPTIX_ERROR_INVALID_VALUE: return "OPTIX_ERROR_INVALID_VALUE";
    case OPTIX_ERROR_LIBRARY_NOT_FOUND: return "OPTIX_ERROR_LIBRARY_NOT_FOUND";
    case OPTIX_ERROR_ENTRY_SYMBOL_NOT_FOUND: return "OPTIX_ERROR_ENTRY_SYMBOL_NOT_FOUND";
    case OPTIX_ERROR_UNSUPPORTED_ABI_VERSION: return "OPTIX_ERROR_UNSUPPORTED_ABI_VERSION";
    case OPTIX_ERROR_FUNCTION_TABLE_SIZE_MISMATCH: return "OPTIX_ERROR_FUNCTION_TABLE_SIZE_MISMATCH";
    case OPTIX_ERROR_LIBRARY_UNLOAD_FAILURE: return "OPTIX_ERROR_LIBRARY_UNLOAD_FAILURE";
    case OPTIX_ERROR_INTERNAL_ERROR: return "OPTIX_ERROR_INTERNAL_ERROR";
    default: return fmt::format("OptixResult {}", static_cast<int>(result));
  }
}

}  // namespace glint::optix
