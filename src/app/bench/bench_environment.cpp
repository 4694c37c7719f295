#include "app/bench/bench_environment.h"

#include "app/bench/run_program.h"
#include "cuda/device_query.h"
#include "gl/gpu_timer.h"

#include <filesystem>
#include <string>

namespace glint::bench {
namespace {

// The folder of the running executable (a build folder inside the work tree, usually).
std::string executable_folder() {
  std::error_code error;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string(".") : exe.parent_path().string();
}

nlohmann::json git_commit(const std::string& folder) {
  const auto head = run_program({"git", "-C", folder, "rev-parse", "HEAD"});
  if (!head || head->exit_code != 0) return nullptr;
  std::string commit = head->output;
  while (!commit.empty() && (commit.back() == '\n' || commit.back() == '\r')) commit.pop_back();
  return commit;
}

}  // namespace

nlohmann::json describe_environment(const HeadlessGlContext& context) {
  const std::string folder = executable_folder();
  nlohmann::json environment;
  environment["glint_version"] = GLINT_VERSION;
  environment["git_commit"] = git_commit(folder);
  if (!environment["git_commit"].is_null()) {
    // `git diff --quiet HEAD` exits 1 when tracked files differ from the commit.
    const auto diff = run_program({"git", "-C", folder, "diff", "--quiet", "HEAD"});
    environment["git_dirty"] = diff && diff->exit_code == 1;
  }
  environment["gl"] = {{"renderer", context.renderer()},
                       {"vendor", context.vendor()},
                       {"version", context.version()},
                       {"pass_timing", pass_timing_name(pass_timing_for_renderer(context.renderer()))}};
  std::string why_none;
  nlohmann::json devices = nlohmann::json::array();
  for (const CudaDeviceInfo& device : query_cuda_devices(&why_none))
    devices.push_back({{"name", device.name},
                       {"compute_capability", device.compute_capability},
                       {"memory_bytes", device.memory_bytes},
                       {"driver_version", device.driver_version}});
  environment["cuda_devices"] = devices;
  if (devices.empty()) environment["cuda_note"] = why_none;
  return environment;
}

}  // namespace glint::bench
