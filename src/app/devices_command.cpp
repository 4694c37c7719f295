#include "app/devices_command.h"

#include "core/error.h"
#include "cuda/device_query.h"
#include "gl/egl_context.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

namespace glint {

void add_devices_command(CLI::App& app, DevicesOptions& options) {
  CLI::App* devices = app.add_subcommand("devices", "List the CUDA GPUs and the OpenGL renderer glint would use");
  devices->add_flag("--json", options.json, "Print JSON instead of text");
}

int run_devices_command(const DevicesOptions& options) {
  std::string why_no_cuda;
  const std::vector<CudaDeviceInfo> gpus = query_cuda_devices(&why_no_cuda);

  // No GL is not an error here: the point of this command is to say what is and is not available.
  std::string gl_renderer, gl_version, gl_problem;
  int egl_device = -1;
  try {
    const HeadlessGlContext context;
    gl_renderer = context.renderer();
    gl_version = context.version();
    egl_device = context.device_index();
  } catch (const Error& e) {
    gl_problem = e.what();
  }

  if (options.json) {
    nlohmann::json j;
    j["cuda"] = nlohmann::json::array();
    for (const CudaDeviceInfo& gpu : gpus)
      j["cuda"].push_back({{"index", gpu.index}, {"name", gpu.name}, {"compute_capability", gpu.compute_capability},
                           {"memory_bytes", gpu.memory_bytes}, {"driver_version", gpu.driver_version}});
    if (gpus.empty()) j["cuda_unavailable"] = why_no_cuda;
    if (gl_problem.empty())
      j["opengl"] = {{"renderer", gl_renderer}, {"version", gl_version}, {"egl_device", egl_device}};
    else
      j["opengl_unavailable"] = gl_problem;
    fmt::print("{}\n", j.dump(2));
    return 0;
  }
  if (gpus.empty()) fmt::print("cuda     none ({})\n", why_no_cuda);
  for (const CudaDeviceInfo& gpu : gpus)
    fmt::print("cuda {}   {} (sm_{}, {:.1f} GiB, driver {}.{})\n", gpu.index, gpu.name, gpu.compute_capability,
               static_cast<double>(gpu.memory_bytes) / (1024.0 * 1024.0 * 1024.0), gpu.driver_version / 1000,
               (gpu.driver_version % 1000) / 10);
  if (gl_problem.empty())
    fmt::print("opengl   {} | {} (EGL device {})\n", gl_renderer, gl_version, egl_device);
  else
    fmt::print("opengl   unavailable ({})\n", gl_problem);
  return 0;
}

}  // namespace glint
