#include "app/mpi/rank_devices.h"

#include "app/mpi/mpi_world.h"
#include "core/error.h"
#include "core/log.h"
#include "cuda/device_select.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <exception>

namespace glint::mpi {

RankDevices choose_rank_devices(int local_rank, const std::vector<EglDeviceDescription>& devices, int cuda_count,
                                const std::optional<int>& egl_override) {
  RankDevices chosen;
  const auto cuda_of = [&](const EglDeviceDescription& device) -> std::optional<int> {
    if (device.cuda_device && *device.cuda_device < cuda_count) return device.cuda_device;
    return std::nullopt;
  };
  if (egl_override) {
    chosen.egl_device = egl_override;
    for (const EglDeviceDescription& device : devices)
      if (device.index == *egl_override) chosen.cuda_device = cuda_of(device);
    chosen.note = fmt::format("EGL device {} from GLINT_EGL_DEVICE", *egl_override);
  } else {
    std::vector<const EglDeviceDescription*> gpus;
    for (const EglDeviceDescription& device : devices)
      if (device.is_nvidia()) gpus.push_back(&device);
    // In CUDA's order when every GPU says its CUDA device (EGL may list them otherwise).
    if (std::all_of(gpus.begin(), gpus.end(), [](const EglDeviceDescription* d) { return d->cuda_device.has_value(); }))
      std::stable_sort(gpus.begin(), gpus.end(),
                       [](const EglDeviceDescription* a, const EglDeviceDescription* b) { return *a->cuda_device < *b->cuda_device; });
    if (!gpus.empty()) {
      const EglDeviceDescription& gpu = *gpus[static_cast<std::size_t>(local_rank) % gpus.size()];
      chosen.egl_device = gpu.index;
      chosen.cuda_device = cuda_of(gpu);
      chosen.note = fmt::format("GPU {} of this host's {} for local rank {}", static_cast<std::size_t>(local_rank) % gpus.size(),
                                gpus.size(), local_rank);
    } else {
      chosen.note = "no NVIDIA EGL device: the default renderer";
    }
  }
  if (!chosen.cuda_device && cuda_count > 0) chosen.cuda_device = local_rank % cuda_count;
  return chosen;
}

RankSession::RankSession() : exceptions_(std::uncaught_exceptions()) {
  try {
    about_ = use_rank_devices();
  } catch (...) {
    mark_command_failed();  // a bad GLINT_EGL_DEVICE on one rank: the others must not wait for it
    throw;
  }
}

RankSession::~RankSession() {
  if (!shared_work_over_ && std::uncaught_exceptions() > exceptions_) mark_command_failed();
}

nlohmann::json use_rank_devices() {
  const Rank& rank = world();
  if (rank.size <= 1) return nullptr;
  std::vector<EglDeviceDescription> devices;
  try {
    devices = list_egl_devices();
  } catch (const Error& error) {
    log_warning("rank {}: cannot list EGL devices ({}); taking the default", rank.rank, error.what());
  }
  std::optional<int> egl_override;
  if (const std::optional<std::string> text = egl_device_override_from_env())
    egl_override = parse_egl_device_override(*text, devices);
  const RankDevices chosen = choose_rank_devices(rank.local_rank, devices, cuda::visible_device_count(), egl_override);
  if (chosen.egl_device && !egl_override) setenv("GLINT_EGL_DEVICE", std::to_string(*chosen.egl_device).c_str(), 1);
  if (chosen.cuda_device) cuda::use_device(*chosen.cuda_device);
  nlohmann::json about = {{"rank", rank.rank},
                          {"host", rank.host},
                          {"local_rank", rank.local_rank},
                          {"egl_device", chosen.egl_device ? nlohmann::json(*chosen.egl_device) : nlohmann::json(nullptr)},
                          {"cuda_device", chosen.cuda_device ? nlohmann::json(*chosen.cuda_device) : nlohmann::json(nullptr)},
                          {"devices", chosen.note}};
  if (chosen.egl_device)
    for (const EglDeviceDescription& device : devices)
      if (device.index == *chosen.egl_device && !device.drm_node.empty()) about["drm_node"] = device.drm_node;
  log_info("rank {} of {} on {} (local rank {}): {}", rank.rank, rank.size, rank.host, rank.local_rank, chosen.note);
  return about;
}

}  // namespace glint::mpi
